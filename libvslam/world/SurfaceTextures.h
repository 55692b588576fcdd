#pragma once
/** \file SurfaceTextures.h
 * The images a world's surfaces show: a photograph's part cropped to the
 * surface's aspect ratio (never stretched), or a material's tile (tinted,
 * its contrast scaled) to be repeated at its real size. Photographs are
 * read once, from plain files or package archives (AssetArchive.h).
 */
#include <libvslam/world/FloorPlan.h>
#include <opencv2/core.hpp>

#include <map>
#include <string>

namespace vslam::world
{
/** An image for a surface and how it maps onto it: stretched once over
 * the surface (a photograph) or repeated every tileWidth x tileHeight
 * metres (a material). Rows are flipped for OpenGL: row 0 is the bottom. */
struct SurfaceImage
{
	cv::Mat image;
	bool tiled = false;
	double tileWidth = 1, tileHeight = 1;
};

class SurfaceTextures
{
   public:
	/** maxSide: longest side of a photograph's crop, pixels. */
	SurfaceTextures(const FloorPlan& plan, int maxSide);

	/** What a surface of width x height metres shows; for a photograph,
	 * the crop's left edge starts at `along` (a fraction of the free
	 * width). */
	SurfaceImage surface(const TextureRef& t, double width, double height, double along = 0.5);

	/** Mean colour of what a texture shows (for plain parts beside it). */
	cv::Scalar meanColour(const TextureRef& t);

	/** Forgets the decoded photographs (the scene keeps what it shows). */
	void release()
	{
		m_photos.clear();
		m_tiles.clear();
	}

   private:
	const FloorPlan& m_plan;
	int m_maxSide;
	std::map<std::string, cv::Mat> m_photos;
	std::map<int, cv::Mat> m_tiles;  //!< by material index

	const cv::Mat& photo(const std::string& file);
	const cv::Mat& tile(int material);
};
}  // namespace vslam::world
