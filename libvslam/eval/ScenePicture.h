#pragma once
/** \file ScenePicture.h
 * A saved MRPT 3-D scene (a run's final_map.3Dscene) drawn offscreen to an
 * image, as SceneViewer3D would show it from above and a little to the
 * side: for headless machines, reports and the documentation. Uses MRPT's
 * CFBORender (EGL; Mesa's software rasterizer without a GPU). */
#include <string>

namespace vslam
{
/** Renders \a sceneFile (COpenGLScene::loadFromFile) to \a pngFile,
 * \a width x \a height pixels, white background. Throws InputError if the
 * scene cannot be read, OutputError if the image cannot be written. */
void writeScenePicture(const std::string& sceneFile, const std::string& pngFile, int width = 1200, int height = 900);
}  // namespace vslam
