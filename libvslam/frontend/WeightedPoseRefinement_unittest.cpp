/** The structure-weighted pose refinement of WeightedPoseRefinement.h:
 * with exact points it is the ordinary least-squares fit; with points of
 * mixed depth quality it fits the truth more closely than the unweighted
 * fit and its covariance matches its scatter. */
#include <gtest/gtest.h>
#include <libvslam/frontend/StructureUncertainty.h>
#include <libvslam/frontend/WeightedPoseRefinement.h>

#include <Eigen/Dense>
#include <opencv2/calib3d.hpp>

#include <cmath>
#include <cstdio>
#include <random>

using namespace vslam;

namespace
{
constexpr double kF = 250;
const cv::Matx33d kK(kF, 0, 160, 0, kF, 120, 0, 0, 1);

/** 40 points 2-5 m in front of the camera that built them (at the
 * origin), seen from 1 m to the side and turned 25 deg towards them. */
struct SideView
{
	std::vector<cv::Point3f> truth;
	cv::Mat rvec, tvec;
	std::vector<cv::Point2f> exact;

	explicit SideView(std::mt19937& rng)
	{
		std::uniform_real_distribution<double> u(-1, 1);
		for (int i = 0; i < 40; i++)
			truth.emplace_back(static_cast<float>(1.2 * u(rng)), static_cast<float>(0.5 * u(rng)),
				static_cast<float>(3.5 + 1.5 * u(rng)));
		rvec = (cv::Mat_<double>(3, 1) << 0, 25 * M_PI / 180, 0);
		cv::Mat R;
		cv::Rodrigues(rvec, R);
		tvec = -R * (cv::Mat_<double>(3, 1) << 1.0, 0, 0.3);
		cv::projectPoints(truth, rvec, tvec, cv::Mat(kK), cv::noArray(), exact);
	}

	std::vector<cv::Point2f> seen(std::mt19937& rng, double sigmaPx) const
	{
		std::normal_distribution<double> g;
		std::vector<cv::Point2f> out;
		for (const auto& p : exact)
			out.emplace_back(static_cast<float>(p.x + sigmaPx * g(rng)), static_cast<float>(p.y + sigmaPx * g(rng)));
		return out;
	}

	Eigen::Matrix<double, 6, 1> errorOf(const cv::Mat& r, const cv::Mat& t) const
	{
		Eigen::Matrix<double, 6, 1> e;
		for (int i = 0; i < 3; i++) e(i) = r.at<double>(i) - rvec.at<double>(i), e(3 + i) = t.at<double>(i) - tvec.at<double>(i);
		return e;
	}
};

const Eigen::Vector3d kOrigin = Eigen::Vector3d::Zero();
}  // namespace

TEST(WeightedPoseRefinement, WithExactPointsItIsTheOrdinaryLeastSquaresFit)
{
	std::mt19937 rng(3);
	const SideView v(rng);
	const auto pixels = v.seen(rng, 0.5);
	const std::vector<float> exact(v.truth.size(), 0.0f);
	cv::Mat r = v.rvec.clone(), t = v.tvec.clone();
	Eigen::Matrix<double, 6, 6> cov;
	ASSERT_TRUE(refinePoseWeightedByStructure(v.truth, pixels, exact, kOrigin, kK, 0.5, r, t, cov));
	cv::Mat rLM = v.rvec.clone(), tLM = v.tvec.clone();
	cv::solvePnPRefineLM(v.truth, pixels, cv::Mat(kK), cv::noArray(), rLM, tLM);
	EXPECT_LT(cv::norm(r - rLM), 1e-6);
	EXPECT_LT(cv::norm(t - tLM), 1e-6);

	// Its covariance: sigma^2 (J^T J)^-1, times the reduced chi-square if
	// that exceeds 1.
	Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
	for (const auto& res : poseSolveResiduals(v.truth, {}, kOrigin, r, t, kK))
		A += res.jacobianWrtPose.transpose() * res.jacobianWrtPose;
	std::vector<cv::Point2f> projected;
	cv::projectPoints(v.truth, r, t, cv::Mat(kK), cv::noArray(), projected);
	double chi2 = 0;
	for (size_t k = 0; k < projected.size(); k++)
		chi2 += (std::pow(projected[k].x - pixels[k].x, 2) + std::pow(projected[k].y - pixels[k].y, 2)) / 0.25;
	const Eigen::Matrix<double, 6, 6> expected = 0.25 * A.inverse() * std::max(1.0, chi2 / (2.0 * 40 - 6));
	EXPECT_LT((cov - expected).norm(), 1e-6 * expected.norm());
}

TEST(WeightedPoseRefinement, PointsOfMixedDepthQualityAreWeighedByIt)
{
	// Half the points known to 1% of their distance along the ray from the
	// camera that built them, half to 20% (as near a short forward
	// baseline's direction of motion), each off by a draw of that.
	std::mt19937 rng(8);
	const SideView v(rng);
	std::vector<float> depthStd;
	for (size_t k = 0; k < v.truth.size(); k++) depthStd.push_back(k % 2 ? 0.2f : 0.01f);
	std::normal_distribution<double> g;
	const int trials = 300;
	double sqWeighted = 0, sqPlain = 0, nees = 0;
	int solved = 0;
	for (int trial = 0; trial < trials; trial++)
	{
		std::vector<cv::Point3f> built;
		for (size_t k = 0; k < v.truth.size(); k++) built.push_back(v.truth[k] * static_cast<float>(1 + depthStd[k] * g(rng)));
		const auto pixels = v.seen(rng, 0.5);
		cv::Mat r = v.rvec.clone(), t = v.tvec.clone();
		cv::solvePnPRefineLM(built, pixels, cv::Mat(kK), cv::noArray(), r, t);
		const Eigen::Matrix<double, 6, 1> plain = v.errorOf(r, t);
		Eigen::Matrix<double, 6, 6> cov;
		if (!refinePoseWeightedByStructure(built, pixels, depthStd, kOrigin, kK, 0.5, r, t, cov)) continue;
		solved++;
		const Eigen::Matrix<double, 6, 1> weighted = v.errorOf(r, t);
		sqPlain += plain.squaredNorm();
		sqWeighted += weighted.squaredNorm();
		nees += weighted.dot(cov.inverse() * weighted);
	}
	ASSERT_EQ(solved, trials);
	nees /= trials;
	std::printf("RMS pose error (rvec, tvec): weighted %.4f, unweighted %.4f; mean NEES %.2f (6: consistent)\n",
		std::sqrt(sqWeighted / trials), std::sqrt(sqPlain / trials), nees);
	EXPECT_LT(sqWeighted, 0.5 * sqPlain);
	// A consistent 6-D covariance gives a mean NEES of 6; first order, and
	// the reduced chi-square scaling errs on the large side.
	EXPECT_GT(nees, 6 * 0.6);
	EXPECT_LT(nees, 6 * 1.3);
}

TEST(WeightedPoseRefinement, TooFewPointsLeaveThePoseAsItWas)
{
	std::mt19937 rng(4);
	const SideView v(rng);
	const std::vector<cv::Point3f> three(v.truth.begin(), v.truth.begin() + 3);
	const std::vector<cv::Point2f> pixels(v.exact.begin(), v.exact.begin() + 3);
	cv::Mat r = v.rvec.clone(), t = v.tvec.clone();
	Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Constant(7);
	EXPECT_FALSE(refinePoseWeightedByStructure(three, pixels, {0, 0, 0}, kOrigin, kK, 0.5, r, t, cov));
	EXPECT_EQ(cv::norm(r - v.rvec), 0);
	EXPECT_EQ(cov(0, 0), 7);
}
