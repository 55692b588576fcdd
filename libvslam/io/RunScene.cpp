#include <libvslam/core/OutputError.h>
#include <libvslam/io/COutputFile.h>
#include <libvslam/io/RunScene.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/io/zip.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/serialization/CArchive.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

namespace vslam
{
namespace
{
mrpt::opengl::CSetOfLines::Ptr pathLines(const Trajectory& path, const mrpt::img::TColor& colour, const std::string& name)
{
	auto lines = mrpt::opengl::CSetOfLines::Create();
	lines->setName(name);
	lines->setColor_u8(colour);
	lines->setLineWidth(2);
	for (size_t i = 1; i < path.size(); i++)
		lines->appendLine(path[i - 1].pose.x, path[i - 1].pose.y, 0, path[i].pose.x, path[i].pose.y, 0);
	return lines;
}

/** A landmark's 2-sigma position ellipse as a closed line. (MRPT 2.5's
 * CEllipsoid2D is constructed misaligned by make_shared: UBSan stops on it.) */
mrpt::opengl::CSetOfLines::Ptr ellipseLines(const se2::Pose& at, const Eigen::Matrix2d& cov)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(cov);
	const Eigen::Vector2d radii = 2 * eigen.eigenvalues().cwiseMax(0).cwiseSqrt();
	auto lines = mrpt::opengl::CSetOfLines::Create();
	lines->setName("landmark");
	lines->setColor_u8({0, 0, 0});
	constexpr int kSegments = 36;
	Eigen::Vector2d previous;
	for (int i = 0; i <= kSegments; i++)
	{
		const double a = 2 * M_PI * i / kSegments;
		const Eigen::Vector2d p = Eigen::Vector2d(at.x, at.y) +
			eigen.eigenvectors() * Eigen::Vector2d(radii[0] * std::cos(a), radii[1] * std::sin(a));
		if (i > 0) lines->appendLine(previous.x(), previous.y(), 0, p.x(), p.y(), 0);
		previous = p;
	}
	return lines;
}

/** The floor plan's outlines, each closed. */
mrpt::opengl::CSetOfLines::Ptr floorPlanLines(const std::vector<std::vector<Eigen::Vector2d>>& outlines)
{
	auto lines = mrpt::opengl::CSetOfLines::Create();
	lines->setName("floor plan");
	lines->setColor_u8({120, 120, 120});
	lines->setLineWidth(2);
	for (const auto& outline : outlines)
		for (size_t i = 0; i < outline.size(); i++)
		{
			const Eigen::Vector2d& a = outline[i];
			const Eigen::Vector2d& b = outline[(i + 1) % outline.size()];
			lines->appendLine(a.x(), a.y(), 0, b.x(), b.y(), 0);
		}
	return lines;
}

/** A grid under everything the run saw, 1 m cells. */
mrpt::opengl::CGridPlaneXY::Ptr floorGrid(const RunSceneContent& c)
{
	double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
	const auto extend = [&](double x, double y) {
		x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
	};
	for (const Trajectory* path : {&c.estimated, &c.odometry, &c.truth})
		for (const auto& p : *path) extend(p.pose.x, p.pose.y);
	for (const auto& l : c.landmarks) extend(l.pose.x, l.pose.y);
	for (const auto& outline : c.floorPlan)
		for (const auto& corner : outline) extend(corner.x(), corner.y());
	return mrpt::opengl::CGridPlaneXY::Create(
		std::floor(x0) - 1, std::ceil(x1) + 1, std::floor(y0) - 1, std::ceil(y1) + 1, 0, 1);
}
}  // namespace

void writeRunScene(const std::string& file, const RunSceneContent& c)
{
	mrpt::opengl::COpenGLScene scene;
	scene.insert(floorGrid(c));
	if (!c.floorPlan.empty()) scene.insert(floorPlanLines(c.floorPlan));
	scene.insert(pathLines(c.odometry, {200, 0, 0}, "odometry"));
	if (!c.truth.empty()) scene.insert(pathLines(c.truth, {0, 160, 0}, "ground truth"));
	scene.insert(pathLines(c.estimated, {0, 0, 220}, "estimate"));
	auto headings = mrpt::opengl::CSetOfLines::Create();
	headings->setName("landmark headings");
	headings->setColor_u8({0, 0, 0});
	for (const auto& l : c.landmarks)
	{
		scene.insert(ellipseLines(l.pose, l.positionCov));
		if (l.hasHeading)
			headings->appendLine(l.pose.x, l.pose.y, 0, l.pose.x + 0.3 * std::cos(l.pose.phi),
				l.pose.y + 0.3 * std::sin(l.pose.phi), 0);
	}
	scene.insert(headings);
	// Serialized and gzipped as COpenGLScene::saveToFile does, then written
	// through the checked writer (saveToFile reports no reason for a failure).
	mrpt::io::CMemoryStream serialized;
	mrpt::serialization::archiveFrom(serialized) << scene;
	const auto* bytes = static_cast<const uint8_t*>(serialized.getRawBufferData());
	std::vector<uint8_t> gz;
	if (!mrpt::io::zip::compress_gz_data_block({bytes, bytes + serialized.getTotalBytesCount()}, gz, 1))
		throw OutputError("cannot compress output file '" + file + "'");
	COutputFile out(file, COutputFile::Mode::Atomic);
	out.write(std::string(gz.begin(), gz.end()));
	out.commit();
}
}  // namespace vslam
