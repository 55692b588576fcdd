#include <gtest/gtest.h>
#include <libvslam/frontend/HeadingChange.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <tests/support/NumericalDerivative.h>

using namespace vslam;

namespace
{
constexpr double kDeg = M_PI / 180;

/** The rendered robot's camera: 0.1 m ahead of the axis, 0.35 m up,
 * pitched 8 deg (camera axes: z forward, x right, y down). */
mrpt::poses::CPose3D mountAt(double x, double y)
{
	return mrpt::poses::CPose3D(x, y, 0.35, 0, -8 * kDeg, 0) + mrpt::poses::CPose3D(0, 0, 0, -M_PI / 2, 0, -M_PI / 2);
}

PinholeCamera camera320()
{
	PinholeCamera c;
	c.fx = c.fy = 250;
	c.cx = 159.5;
	c.cy = 119.5;
	return c;
}

/** The robot's motion along an arc: chord d at theta/2, heading change theta. */
mrpt::poses::CPose2D arc(double d, double theta)
{
	return {d * std::cos(theta / 2), d * std::sin(theta / 2), theta};
}

/** A turn in place by theta, then a straight of length d. */
mrpt::poses::CPose2D turnThenDrive(double d, double theta)
{
	return {d * std::cos(theta), d * std::sin(theta), theta};
}

/** Two images of random scene points (1-6 m ahead of the robot, or
 * `nearest`-`farthest`, spread across the view)
 * seen from the robot at the origin and after `motion`, with pixel noise,
 * the same random descriptor in both images (slightly perturbed), and
 * `outliers` matches whose second position is random. */
struct ImagePair
{
	ImageFeatures first, second;
};

ImagePair makePair(const mrpt::poses::CPose3D& mount, const mrpt::poses::CPose2D& motion, double pixelNoise,
	int points, int outliers, std::mt19937& rng, double nearest = 1, double farthest = 6,
	const mrpt::poses::CPose3D& shake = mrpt::poses::CPose3D())
{
	std::uniform_real_distribution<double> U(0, 1);
	std::normal_distribution<double> N(0, 1);
	const PinholeCamera cam = camera320();
	const mrpt::poses::CPose3D cam1 = mount, cam2 = mrpt::poses::CPose3D(motion) + mount + shake;
	ImagePair p;
	p.first.camera = p.second.camera = cam;
	std::vector<cv::Mat> rows1, rows2;
	auto inImage = [](const cv::Point2d& q) { return q.x >= 0 && q.x < 320 && q.y >= 0 && q.y < 240; };
	auto descriptor = [&]() {
		cv::Mat d(1, 128, CV_32F);
		for (int k = 0; k < 128; k++) d.at<float>(0, k) = static_cast<float>(std::abs(N(rng)));
		return d;
	};
	auto perturbed = [&](const cv::Mat& d) {
		cv::Mat e = d.clone();
		for (int k = 0; k < 128; k++) e.at<float>(0, k) += static_cast<float>(0.02 * N(rng));
		return e;
	};
	int made = 0;
	while (made < points)
	{
		// A point in the robot's start frame, ahead and to the sides.
		// Near the camera, heights around its own, so the points are in view.
		const double depth = nearest + (farthest - nearest) * U(rng), side = (U(rng) - 0.5) * 1.6 * depth;
		const double height = depth >= 1 ? 2.0 * U(rng) : 0.35 + (U(rng) - 0.5) * 1.2 * depth;
		const mrpt::math::TPoint3D X(depth, side, height);
		mrpt::math::TPoint3D c1, c2;
		cam1.inverseComposePoint(X, c1);
		cam2.inverseComposePoint(X, c2);
		if (c1.z < 0.1 || c2.z < 0.1) continue;
		const cv::Point2d q1 = cam.project({c1.x, c1.y, c1.z}), q2 = cam.project({c2.x, c2.y, c2.z});
		if (!inImage(q1) || !inImage(q2)) continue;
		const cv::Mat d = descriptor();
		p.first.pixels.emplace_back(
			static_cast<float>(q1.x + pixelNoise * N(rng)), static_cast<float>(q1.y + pixelNoise * N(rng)));
		p.second.pixels.emplace_back(
			static_cast<float>(q2.x + pixelNoise * N(rng)), static_cast<float>(q2.y + pixelNoise * N(rng)));
		rows1.push_back(d);
		rows2.push_back(perturbed(d));
		made++;
	}
	for (int i = 0; i < outliers; i++)
	{
		const cv::Mat d = descriptor();
		p.first.pixels.emplace_back(static_cast<float>(320 * U(rng)), static_cast<float>(240 * U(rng)));
		p.second.pixels.emplace_back(static_cast<float>(320 * U(rng)), static_cast<float>(240 * U(rng)));
		rows1.push_back(d);
		rows2.push_back(perturbed(d));
	}
	cv::vconcat(rows1, p.first.descriptors);
	cv::vconcat(rows2, p.second.descriptors);
	return p;
}

/** The heading std of the rendered robot's odometry for a motion
 * (sigma_R 0.05 rad/sqrt(rad), 0.02 rad/sqrt(m) per metre): what the
 * visual heading change must beat. */
double odometryHeadingStd(double d, double theta)
{
	return std::sqrt(0.05 * 0.05 * std::abs(theta) + 0.02 * 0.02 * std::abs(d));
}

Eigen::Vector3d randomRay(std::mt19937& rng)
{
	std::uniform_real_distribution<double> U(-0.6, 0.6);
	return {U(rng), U(rng) * 0.75, 1.0};
}
}  // namespace

TEST(HeadingChange, ResidualDerivativesMatchTheNumericalOnes)
{
	std::mt19937 rng(3);
	// A camera ahead of the axis moving forwards and backwards, the same
	// turning in place, and a camera on the axis turning in place (rotation
	// only).
	const std::vector<std::pair<mrpt::poses::CPose3D, double>> cases = {
		{mountAt(0.1, 0), 0.06}, {mountAt(0.1, 0), -0.04}, {mountAt(0.1, 0.02), 0.0}, {mountAt(0, 0), 0.0}};
	for (const auto& [mount, chord] : cases)
	{
		const PlanarEpipolarModel model(mount, chord);
		for (int k = 0; k < 20; k++)
		{
			const Eigen::Vector3d r1 = randomRay(rng), r2 = randomRay(rng);
			const double theta = (k - 10) * 2 * kDeg + 0.3 * kDeg, alpha = theta * (k % 3) / 2 - 0.5 * kDeg;
			double dTheta = 0, dAlpha = 0;
			model.residual(r1, r2, theta, alpha, &dTheta, &dAlpha);
			Eigen::VectorXd x(2);
			x << theta, alpha;
			const Eigen::MatrixXd numeric = vslam::testing::numericalJacobian(
				[&](const Eigen::VectorXd& v) { return Eigen::VectorXd::Constant(1, model.residual(r1, r2, v[0], v[1])); },
				x);
			EXPECT_NEAR(dTheta, numeric(0, 0), 1e-6 * std::max(1.0, std::abs(dTheta)))
				<< "chord " << chord << ", theta " << theta;
			EXPECT_NEAR(dAlpha, numeric(0, 1), 1e-6 * std::max(1.0, std::abs(dAlpha)))
				<< "chord " << chord << ", theta " << theta;
		}
	}
}

TEST(HeadingChange, WobbleDerivativesMatchTheNumericalOnes)
{
	std::mt19937 rng(4);
	for (const auto& [mount, chord] : std::vector<std::pair<mrpt::poses::CPose3D, double>>{
			 {mountAt(0.1, 0), 0.06}, {mountAt(0.1, 0), 0.0}, {mountAt(0, 0), 0.0}})
	{
		const PlanarEpipolarModel model(mount, chord);
		const Eigen::Matrix3d& axes = model.wobbleAxes();
		// The axes are perpendicular to each other and to the robot's vertical.
		EXPECT_NEAR((axes.transpose() * axes - Eigen::Matrix3d::Identity()).norm(), 0, 1e-12);
		EXPECT_NEAR((axes.col(2) - mount.getRotationMatrix().asEigen().transpose() * Eigen::Vector3d::UnitZ()).norm(), 0, 1e-12);
		const Eigen::Matrix3d wobble = Eigen::AngleAxisd(0.7 * kDeg, Eigen::Vector3d(0.3, 0.2, 0.9).normalized()).toRotationMatrix();
		for (int k = 0; k < 20; k++)
		{
			const Eigen::Vector3d r1 = randomRay(rng), r2 = randomRay(rng);
			const double theta = (k - 10) * 2 * kDeg + 0.3 * kDeg;
			double dWobble[2] = {0, 0};
			PlanarEpipolarModel::residual(model.motion(theta, theta / 2, wobble), r1, r2, nullptr, nullptr, dWobble);
			const Eigen::MatrixXd numeric = vslam::testing::numericalJacobian(
				[&](const Eigen::VectorXd& w) {
					const Eigen::Vector3d v = axes.leftCols<2>() * w;
					const Eigen::Matrix3d turned = wobble *
						(v.norm() > 0 ? Eigen::AngleAxisd(v.norm(), v.normalized()).toRotationMatrix() : Eigen::Matrix3d::Identity());
					return Eigen::VectorXd::Constant(1, PlanarEpipolarModel::residual(model.motion(theta, theta / 2, turned), r1, r2));
				},
				Eigen::VectorXd::Zero(2));
			for (int a = 0; a < 2; a++)
				EXPECT_NEAR(dWobble[a], numeric(0, a), 1e-6 * std::max(1.0, std::abs(dWobble[a])))
					<< "chord " << chord << ", theta " << theta << ", axis " << a;
		}
	}
}

TEST(HeadingChange, AShakenCameraStillGivesTheHeadingChange)
{
	// The floor pitches and rolls the camera between the two images (here
	// by 0.5 deg std about each axis, more than a floor does): a fit of the
	// heading change alone turns it to explain the shake (with the camera
	// tilted, a roll moves the image sideways like a turn) and trusts the
	// result; with the shake in the model the error is a small part of the
	// shake and the predicted std says how large it is.
	std::mt19937 rng(8);
	std::normal_distribution<double> N(0, 1);
	const auto mount = mountAt(0.1, 0);
	double sumSquaredNormalized = 0;
	std::vector<double> errors;
	const int trials = 200;
	for (int k = 0; k < trials; k++)
	{
		const double theta = (k % 5 - 2) * 3 * kDeg, d = 0.05;
		// Camera axes: pitch about x, roll about z (CPose3D: yaw about z, roll about x).
		const mrpt::poses::CPose3D shake(0, 0, 0, 0.5 * kDeg * N(rng), 0, 0.5 * kDeg * N(rng));
		const ImagePair p = makePair(mount, arc(d, theta), 0.3, 120, 20, rng, 1, 6, shake);
		const auto e = estimateHeadingChange(p.first, p.second, mount, d, THeadingEstimationOptions());
		ASSERT_TRUE(e) << k;
		const double z = (e->dphi - theta) / e->stdDphi;
		sumSquaredNormalized += z * z;
		errors.push_back(std::abs(e->dphi - theta));
	}
	std::nth_element(errors.begin(), errors.begin() + trials / 2, errors.end());
	EXPECT_LT(errors[trials / 2], 0.05 * kDeg);  // a tenth of the shake, a quarter of the odometry's error
	EXPECT_LT(std::sqrt(sumSquaredNormalized / trials), 1.5);
}

TEST(HeadingChange, ResidualVanishesForTheTrueMotionOnly)
{
	std::mt19937 rng(5);
	const auto mount = mountAt(0.1, 0);
	for (const auto& [d, theta] : std::vector<std::pair<double, double>>{{0.06, 0.0}, {0.06, 4 * kDeg}, {0.0, -15 * kDeg}})
	{
		const ImagePair p = makePair(mount, arc(d, theta), 0.0, 40, 0, rng);
		const PlanarEpipolarModel model(mount, d);
		double atTruth = 0, off = 0;
		for (size_t i = 0; i < p.first.size(); i++)
		{
			const cv::Point3d a = p.first.camera.ray(p.first.pixels[i]), b = p.second.camera.ray(p.second.pixels[i]);
			const Eigen::Vector3d r1(a.x, a.y, a.z), r2(b.x, b.y, b.z);
			atTruth = std::max(atTruth, std::abs(model.residual(r1, r2, theta, theta / 2)));
			off += std::abs(model.residual(r1, r2, theta + 0.5 * kDeg, theta / 2));
		}
		// float pixel positions: about 1e-5 px. Half a degree off moves the
		// points across their epipolar lines by tenths of a pixel on average
		// when driving; turning in place the camera (ahead of the axis) moves
		// sideways, its epipolar lines lie nearly along the motion a turn
		// gives the points, and the distance is a few hundredths.
		EXPECT_LT(atTruth * 250, 1e-3) << d << " " << theta;
		EXPECT_GT(off * 250 / static_cast<double>(p.first.size()), d > 0 ? 0.3 : 0.03) << d << " " << theta;
	}
}

TEST(HeadingChange, RecoversTheHeadingChangeWithNoiseAndOutliers)
{
	std::mt19937 rng(7);
	const auto mount = mountAt(0.1, 0);
	const THeadingEstimationOptions settings;
	// Straight, gentle arcs, a turn in place and a fast turn while moving.
	const std::vector<std::pair<double, double>> motions = {
		{0.06, 0.0}, {0.06, 2 * kDeg}, {0.05, -5 * kDeg}, {0.0, 20 * kDeg}, {0.03, -30 * kDeg}};
	for (const auto& [d, theta] : motions)
	{
		const ImagePair p = makePair(mount, arc(d, theta), 0.3, 200, 60, rng);
		const auto e = estimateHeadingChange(p.first, p.second, mount, d, settings);
		ASSERT_TRUE(e) << d << " " << theta;
		EXPECT_NEAR(e->dphi, theta, 4 * e->stdDphi) << d << " " << theta;
		// 0.3 px over 250 px and ~200 points: several times the odometry's
		// precision, also turning in place, where the camera moves sideways
		// and the epipolar lines lie along the shift a turn gives the points.
		EXPECT_LT(e->stdDphi, odometryHeadingStd(d, theta) / 3) << d << " " << theta;
		EXPECT_GE(e->inliers, 190);
		EXPECT_LE(e->inliers, 205);  // a few outliers fall on an epipolar line by chance
		EXPECT_EQ(e->matches, 260);
		EXPECT_NEAR(e->rmsPx, 0.3, 0.15);
	}
}

TEST(HeadingChange, ATurnThenAStraightIsNoArcButFitsToo)
{
	// The chord then lies along the new heading, theta/2 off the arc's:
	// within alpha's prior, so the estimate stays right and says how sure
	// it is.
	std::mt19937 rng(9);
	const auto mount = mountAt(0.1, 0);
	for (const double theta : {6 * kDeg, -6 * kDeg, 10 * kDeg})
	{
		const ImagePair p = makePair(mount, turnThenDrive(0.03, theta), 0.3, 200, 40, rng);
		const auto e = estimateHeadingChange(p.first, p.second, mount, 0.03, THeadingEstimationOptions());
		ASSERT_TRUE(e) << theta;
		EXPECT_NEAR(e->dphi, theta, 4 * e->stdDphi) << theta;
		// The camera's shake in the model ties the heading to the chord's
		// direction a little more here: still more than twice the odometry's precision.
		EXPECT_LT(e->stdDphi, odometryHeadingStd(0.03, theta) / 2) << theta;
	}
}

TEST(HeadingChange, PredictedStdMatchesTheScatter)
{
	std::mt19937 rng(11);
	const auto mount = mountAt(0.1, 0);
	double sumSquaredNormalized = 0;
	const int trials = 240;
	for (int k = 0; k < trials; k++)
	{
		// Arcs, turns then straights, and straights then turns.
		const double theta = (k % 7 - 3) * 3 * kDeg;
		const int kind = k % 3;
		const double alpha = kind == 0 ? theta / 2 : kind == 1 ? theta : 0;
		const mrpt::poses::CPose2D motion(0.05 * std::cos(alpha), 0.05 * std::sin(alpha), theta);
		const ImagePair p = makePair(mount, motion, 0.5, 60, 10, rng);
		const auto e = estimateHeadingChange(p.first, p.second, mount, 0.05, THeadingEstimationOptions());
		ASSERT_TRUE(e);
		const double z = (e->dphi - theta) / e->stdDphi;
		sumSquaredNormalized += z * z;
	}
	// The fit's own variance (inliers cut at 1.5 px, 3 sigma of this noise)
	// plus the chord direction's prior spread: the normalized errors have
	// about unit variance over this mix. (A fit of theta and alpha together
	// gave 1.5 here, trusting its alpha 2.5 times too much.)
	const double rms = std::sqrt(sumSquaredNormalized / trials);
	EXPECT_GT(rms, 0.8);
	EXPECT_LT(rms, 1.25);
}

TEST(HeadingChange, AWrongDistanceMovesTheEstimateLittle)
{
	// The chord comes from odometry: 20% off changes only the parallax of
	// near points, which the fit sees in the residuals.
	std::mt19937 rng(13);
	const auto mount = mountAt(0.1, 0);
	double worst = 0;
	for (int k = 0; k < 20; k++)
	{
		const double theta = (k % 5 - 2) * 4 * kDeg;
		const ImagePair p = makePair(mount, arc(0.06, theta), 0.3, 150, 0, rng);
		const auto exact = estimateHeadingChange(p.first, p.second, mount, 0.06, THeadingEstimationOptions());
		const auto off = estimateHeadingChange(p.first, p.second, mount, 0.072, THeadingEstimationOptions());
		ASSERT_TRUE(exact && off);
		worst = std::max(worst, std::abs(off->dphi - exact->dphi));
	}
	EXPECT_LT(worst, 0.1 * kDeg);
}

TEST(HeadingChange, ACameraOnTheAxisTurningInPlaceIsARotation)
{
	std::mt19937 rng(17);
	const auto mount = mountAt(0, 0);
	const ImagePair p = makePair(mount, arc(0, -12 * kDeg), 0.3, 150, 30, rng);
	const auto e = estimateHeadingChange(p.first, p.second, mount, 0, THeadingEstimationOptions());
	ASSERT_TRUE(e);
	EXPECT_NEAR(e->dphi, -12 * kDeg, 4 * e->stdDphi);
}

TEST(HeadingChange, ASlipTheOdometryMissedNearASurfaceGivesNothing)
{
	// Turning in place 11.5 deg a quarter metre from a textured surface (the
	// camera is 0.1 m ahead of the robot's axis),
	// the robot also slips 3 cm sideways, which odometry does not see (chord
	// 0): the parallax of that slip is several degrees, and a fit of the turn
	// alone ends far from the truth. Its inliers' bearing changes are then
	// further from its theta than any parallax the assumed motion can give:
	// no estimate, rather than a wrong one (the rendered living room's worst
	// case).
	std::mt19937 rng(23);
	const auto mount = mountAt(0.1, 0);
	const double theta = -11.46 * kDeg;
	const mrpt::poses::CPose2D slipped(0.0, -0.03, theta);
	int estimates = 0, wrong = 0;
	for (int k = 0; k < 20; k++)
	{
		const ImagePair p = makePair(mount, slipped, 0.3, 150, 0, rng, 0.32, 0.42);
		const auto e = estimateHeadingChange(p.first, p.second, mount, 0.0, THeadingEstimationOptions());
		if (!e) continue;
		estimates++;
		if (std::abs(e->dphi - theta) > 4 * e->stdDphi) wrong++;
	}
	EXPECT_EQ(wrong, 0) << estimates << " estimates";
	// Without the slip the same scene is measured.
	const ImagePair p = makePair(mount, arc(0.0, theta), 0.3, 150, 0, rng, 0.32, 0.42);
	const auto e = estimateHeadingChange(p.first, p.second, mount, 0.0, THeadingEstimationOptions());
	ASSERT_TRUE(e);
	EXPECT_NEAR(e->dphi, theta, 4 * e->stdDphi);
}

TEST(HeadingChange, ARobotStandingStillTurnsByNothing)
{
	// Chord 0 and no turn: the camera does not move, the essential matrix
	// is zero at theta = 0 and only its limit direction says anything.
	std::mt19937 rng(29);
	const auto mount = mountAt(0.1, 0);
	const ImagePair p = makePair(mount, arc(0.0, 0.0), 0.3, 150, 20, rng);
	const auto e = estimateHeadingChange(p.first, p.second, mount, 0.0, THeadingEstimationOptions());
	ASSERT_TRUE(e);
	EXPECT_NEAR(e->dphi, 0.0, std::max(4 * e->stdDphi, 0.01 * kDeg));
}

TEST(HeadingChange, UnrelatedImagesOrTooFewFeaturesGiveNothing)
{
	std::mt19937 rng(19);
	const auto mount = mountAt(0.1, 0);
	const ImagePair a = makePair(mount, arc(0.06, 0), 0.3, 150, 0, rng);
	const ImagePair b = makePair(mount, arc(0.06, 0), 0.3, 150, 0, rng);
	// Different scenes: no descriptor passes the ratio test against the other.
	EXPECT_FALSE(estimateHeadingChange(a.first, b.second, mount, 0.06, THeadingEstimationOptions()));
	// Matching descriptors but the positions of another scene: no consensus.
	ImageFeatures scrambled = b.second;
	scrambled.descriptors = a.second.descriptors;
	EXPECT_FALSE(estimateHeadingChange(a.first, scrambled, mount, 0.06, THeadingEstimationOptions()));
	const ImagePair few = makePair(mount, arc(0.06, 0), 0.3, 15, 0, rng);
	EXPECT_FALSE(estimateHeadingChange(few.first, few.second, mount, 0.06, THeadingEstimationOptions()));
}
