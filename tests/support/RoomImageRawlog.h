#pragma once
/** \file RoomImageRawlog.h
 * Test fixture: an image rawlog (actions/sensory frames) of a robot driving
 * circles in the textured room of RoomRenderer.h, images at 2 Hz, with the
 * true path as a TUM file. Odometry can carry a scale bias. Images are
 * embedded, or stored externally in <rawlog name>_Images/ (MRPT's layout).
 */
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/RawlogWriting.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationImage.h>
#include <tests/support/RoomRenderer.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace vslam::testing
{
struct TRoomRawlogOptions
{
	double laps = 1.5;
	double odometryScale = 1.0;  //!< odometry distances times this
	double odometryTurnScale = 1.0;  //!< odometry rotations times this
	bool externalImages = false;
	/** The circle driven (centred in the room) and where on it the robot starts. */
	double radius = 1.0;  //!< m
	double startAngle = 0;  //!< rad
	/** Image brightness times this (another time of day). */
	double brightness = 1.0;
	/** Image width in pixels (height 3/4 of it; the same field of view). */
	int imageWidth = 320;
};

/** Writes `rawlog` and `<rawlog stem>_groundtruth.tum`; returns the image count. */
inline int writeRoomImageRawlog(const std::string& rawlog, const TRoomRawlogOptions& o = {})
{
	RoomRenderer room(5.0, 4.0, 2.5, 42);
	mrpt::img::TCamera cam;
	const double scale = o.imageWidth / 320.0;
	cam.ncols = o.imageWidth;
	cam.nrows = o.imageWidth * 3 / 4;
	cam.setIntrinsicParamsFromValues(250 * scale, 250 * scale, 160 * scale, 120 * scale);
	const mrpt::poses::CPose3D mount(0.1, 0, 0.3, -M_PI / 2, 0, -M_PI / 2);
	const std::string imagesDir = CRawlogReader::imagesDirectory(rawlog);
	if (o.externalImages) std::filesystem::create_directories(imagesDir);
	std::ofstream gt(siblingFile(rawlog, "_groundtruth.tum"));
	gt << std::setprecision(12);
	std::vector<ActionFramePair> steps;
	const double radius = o.radius, step = 0.075;
	const int frames = static_cast<int>(o.laps * 2 * M_PI * radius / step);
	mrpt::poses::CPose2D previous;
	for (int k = 0; k < frames; k++)
	{
		const double a = o.startAngle + k * step / radius, t = 1e9 + 0.5 * k;
		const mrpt::poses::CPose2D robot(2.5 + radius * std::cos(a), 2.0 + radius * std::sin(a), a + M_PI / 2);
		gt << t << " " << robot.x() << " " << robot.y() << " 0 0 0 " << std::sin(robot.phi() / 2) << " "
		   << std::cos(robot.phi() / 2) << "\n";
		auto acts = mrpt::obs::CActionCollection::Create();
		if (k > 0)
		{
			mrpt::poses::CPose2D inc = robot - previous;
			inc.x(inc.x() * o.odometryScale);
			inc.y(inc.y() * o.odometryScale);
			inc.phi(inc.phi() * o.odometryTurnScale);
			mrpt::obs::CActionRobotMovement2D mv;
			mv.computeFromOdometry(inc, {});
			mv.timestamp = mrpt::Clock::fromDouble(t);
			acts->insert(mv);
		}
		previous = robot;
		auto obs = mrpt::obs::CObservationImage::Create();
		obs->timestamp = mrpt::Clock::fromDouble(t);
		obs->sensorLabel = "CAMERA";
		obs->cameraParams = cam;
		obs->cameraPose = mount;
		cv::Mat img = room.render(cam, mrpt::poses::CPose3D(robot) + mount);
		if (o.brightness != 1.0) img.convertTo(img, -1, o.brightness);
		if (o.externalImages)
		{
			const std::string name = "img_" + std::to_string(k) + ".png";
			mrpt::img::CImage(img, mrpt::img::DEEP_COPY).saveToFile(imagesDir + "/" + name);
			obs->image.setExternalStorage(name);
		}
		else
			obs->image = mrpt::img::CImage(img, mrpt::img::DEEP_COPY);
		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(obs);
		steps.emplace_back(acts, sf);
	}
	writeActionFrameRawlog(rawlog, steps);
	return frames;
}
}  // namespace vslam::testing
