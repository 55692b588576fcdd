#pragma once
/** \file FloorPlanFile.h
 * The world file of the rendered simulator: one item per line, '#' starts
 * a comment, lengths in metres, angles in degrees.
 *
 *     ceiling_height H
 *     floor   TEXTURE
 *     wall    X1 Y1 X2 Y2 THICKNESS FRONT_TEXTURE [BACK_TEXTURE]
 *     box     X Y YAW SIZE_X SIZE_Y HEIGHT TEXTURE
 *     picture X1 Y1 X2 Y2 Z0 Z1 TEXTURE
 *     door    X1 Y1 X2 Y2 TEXTURE
 *
 * TEXTURE is a photograph, relative to the texture folder (or absolute),
 * optionally followed by "@U0,V0,U1,V1": the part of it used, as fractions,
 * and by "~": mirrored left-right.
 * Any error (unknown item, wrong field count, bad number, missing texture
 * file, degenerate geometry, a world without walls) is an InputError naming
 * the file and line.
 */
#include <libvslam/world/FloorPlan.h>

#include <string>

namespace vslam::world
{
FloorPlan parseFloorPlan(
	const std::string& text, const std::string& fileName, const std::string& textureDir);

FloorPlan loadFloorPlan(const std::string& file, const std::string& textureDir);
}  // namespace vslam::world
