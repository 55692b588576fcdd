/** The shipped worlds give the front-end texture everywhere: a camera
 * 1.2 m in front of the middle of every textured wall face and every box
 * side, at the robot's camera height, sees enough SIFT features. */
#include <gtest/gtest.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/sim/CameraImaging.h>
#include <libvslam/sim/CameraRenderer.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/FreeSpace.h>
#include <libvslam/world/WorldScene.h>

#include <algorithm>
#include <cmath>

using namespace vslam;

namespace
{
struct Face
{
	Eigen::Vector2d a, b;  //!< the face is on the left of a -> b
	std::string what;
	int line = 0;  //!< of its item in the world file
};

std::vector<Face> texturedFaces(const world::FloorPlan& plan)
{
	std::vector<Face> faces;
	for (const auto& w : plan.walls)
	{
		const Eigen::Vector2d d = (w.b - w.a).normalized(), n(-d[1], d[0]);
		faces.push_back({w.a + 0.5 * w.thickness * n, w.b + 0.5 * w.thickness * n,
			"front of the wall on line " + std::to_string(w.line), w.line});
		if (w.hasBack)
			faces.push_back({w.b - 0.5 * w.thickness * n, w.a - 0.5 * w.thickness * n,
				"back of the wall on line " + std::to_string(w.line), w.line});
	}
	for (const auto& b : plan.boxes)
	{
		const auto c = world::footprint(b);
		for (size_t i = 0; i < 4; i++)
			faces.push_back({c[(i + 1) % 4], c[i], "side " + std::to_string(i) + " of the box on line " + std::to_string(b.line),
				b.line});
	}
	return faces;
}

/** The view as the simulated camera delivers it once its exposure has
 * settled on it (the rendered light alone is dimmer on walls facing away
 * from the light). */
cv::Mat exposed(const cv::Mat& rendered)
{
	CameraImaging camera(TCameraImagingOptions(), 250, 1);
	cv::Mat img;
	for (int i = 0; i < 20; i++)
	{
		img = rendered.clone();
		FrameConditions f;
		f.noiseSeed = static_cast<uint64_t>(i);
		camera.capture(img, f);
	}
	return img;
}

/** Faces the robot can see from the front: the viewpoint 1.2 m (else 0.8
 * or 1.6 m) in front of the face's middle must be free space reachable
 * from `start` (box sides against a wall are not), with no other
 * obstacle in between (a wall behind a sofa shows the sofa, tested as
 * the sofa's side). */
void expectTextureOnEveryFace(const std::string& worldFile, const Eigen::Vector2d& start)
{
	const auto plan = world::loadFloorPlan(std::string(VSLAM_SOURCE_DIR) + "/config_ini/worlds/" + worldFile, "/usr/share");
	world::WorldScene scene(plan, 0, CVisualSimulator::TOptions().texture_max_side);
	mrpt::img::TCamera cam;
	cam.ncols = 320, cam.nrows = 240;
	cam.setIntrinsicParamsFromValues(250, 250, 159.5, 119.5);
	cam.dist.fill(0);
	CameraRenderer renderer(cam);
	// The textures' own features: these views have no camera noise to blur away.
	CFeatureExtractor::TOptions features;
	features.sift_denoise_sigma = 0;
	const CFeatureExtractor extractor(features);
	const auto calibration = CImageCalibration::from(cam, 320, 240, CImageCalibration::TOptions(), "test");
	const world::FreeSpace free(plan, 0.2, start);
	const auto segments = plan.obstacleSegments();
	std::vector<size_t> counts;
	size_t hidden = 0;
	for (const auto& f : texturedFaces(plan))
	{
		const Eigen::Vector2d mid = 0.5 * (f.a + f.b), along = (f.b - f.a).normalized();
		const Eigen::Vector2d normal(-along[1], along[0]);  // out of the face
		Eigen::Vector2d eye(NAN, NAN);
		const auto inSight = [&](const Eigen::Vector2d& eye) {
			for (const auto& s : segments)
				if (s.line != f.line && world::segmentSegmentDistance(eye, mid + 0.01 * normal, s.a, s.b) == 0)
					return false;
			return true;
		};
		for (double distance : {1.2, 0.8, 1.6})
			if (free.isFree(mid + distance * normal) && inSight(mid + distance * normal))
			{
				eye = mid + distance * normal;
				break;
			}
		if (std::isnan(eye[0]))
		{
			hidden++;
			continue;
		}
		const double yaw = std::atan2(-normal[1], -normal[0]);
		const mrpt::poses::CPose3D camera = mrpt::poses::CPose3D(eye[0], eye[1], 0.35, yaw, 0, 0) +
			mrpt::poses::CPose3D(0, 0, 0, -M_PI / 2, 0, -M_PI / 2);
		const cv::Mat img = exposed(renderer.render(scene.scene(), camera));
		const size_t n = extractor.extract(img, calibration).size();
		EXPECT_GE(n, 100u) << worldFile << ": " << f.what;
		counts.push_back(n);
	}
	std::sort(counts.begin(), counts.end());
	ASSERT_GT(counts.size(), 10u);
	std::printf("%s: %zu faces seen (%zu hidden), SIFT features per view: min %zu, median %zu\n", worldFile.c_str(),
		counts.size(), hidden, counts.front(), counts[counts.size() / 2]);
}
}  // namespace

TEST(RenderedWorlds, EveryTexturedFaceOfTheLivingRoomGivesFeatures)
{
	expectTextureOnEveryFace("living_room.world", {2.0, 1.0});
}

TEST(RenderedWorlds, EveryTexturedFaceOfTheApartmentGivesFeatures)
{
	expectTextureOnEveryFace("apartment.world", {1.0, 0.9});
}
