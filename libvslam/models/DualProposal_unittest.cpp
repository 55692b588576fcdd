#include <gtest/gtest.h>
#include <libvslam/models/CLandmarkModel.h>
#include <mrpt/random/RandomGenerators.h>

using namespace vslam;

namespace
{
/** Riemann sum of exp(logDensity) over a box in (x, y, phi). */
double integrate(
	const CDualProposal& q, double x0, double x1, double y0, double y1, int n,
	int nPhi)
{
	const double dx = (x1 - x0) / n, dy = (y1 - y0) / n, dphi = 2 * M_PI / nPhi;
	double sum = 0;
	for (int i = 0; i < n; i++)
		for (int j = 0; j < n; j++)
			for (int k = 0; k < nPhi; k++)
				sum += std::exp(q.logDensity(
					{x0 + (i + 0.5) * dx, y0 + (j + 0.5) * dy,
					 -M_PI + (k + 0.5) * dphi}));
	return sum * dx * dy * dphi;
}

LandmarkEstimate point(double x, double y)
{
	LandmarkEstimate l;
	l.kind = LandmarkKind::Point;
	l.mean << x, y, 0;
	l.cov.setZero();
	l.cov.topLeftCorner<2, 2>() << 0.02, 0.005, 0.005, 0.03;
	return l;
}

LandmarkMeasurement rangeBearing(double r, double b)
{
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Point, 1};
	m.z.resize(2);
	m.z << r, b;
	m.R = MatN(2, 2);
	m.R << 0.01, 0, 0, 0.003;
	m.sensorPose = {0.1, 0.0, 0.0};
	return m;
}
}  // namespace

TEST(DualProposal, PointProposalDensityIntegratesToOne)
{
	const auto& model = landmarkModel(LandmarkKind::Point);
	const auto q = model.dualProposal(
		point(0, 0), rangeBearing(1.0, 0.2), HeadingPrior::Gaussian(0.3, 0.2));
	EXPECT_NEAR(integrate(q, -3, 3, -3, 3, 120, 90), 1.0, 0.01);
	const auto qu = model.dualProposal(
		point(0, 0), rangeBearing(1.0, 0.2), HeadingPrior::Uniform());
	EXPECT_NEAR(integrate(qu, -3, 3, -3, 3, 120, 90), 1.0, 0.01);
}

TEST(DualProposal, PoseProposalDensityIntegratesToOne)
{
	const PoseGaussianProposal p = makePoseGaussianProposal(
		{0.5, -0.2, 3.0},
		(Eigen::Matrix3d() << 0.04, 0.01, 0, 0.01, 0.05, 0.002, 0, 0.002, 0.09)
			.finished());
	ASSERT_TRUE(p.valid);
	EXPECT_NEAR(integrate(CDualProposal(p), -1.5, 2.5, -2.2, 1.8, 120, 180), 1.0, 0.01);
}

TEST(DualProposal, SamplesFollowTheDensity)
{
	// Importance-sampling identity: E_q[f/q] = integral of f = 1, for a
	// normalized Gaussian f inside the bulk of q (so f/q stays bounded);
	// this fails if sample() and logDensity() disagree.
	const auto& model = landmarkModel(LandmarkKind::Point);
	const auto q = model.dualProposal(
		point(1, 1), rangeBearing(1.5, -0.4), HeadingPrior::Gaussian(0.1, 0.3));
	const PoseGaussianProposal f = makePoseGaussianProposal(
		q.sample(*std::make_unique<mrpt::random::CRandomGenerator>(3)),
		Eigen::Vector3d(0.005, 0.005, 0.005).asDiagonal());
	const CDualProposal fd(f);
	mrpt::random::CRandomGenerator rng(11);
	double sum = 0;
	const int N = 200000;
	for (int i = 0; i < N; i++)
	{
		const se2::Pose s = q.sample(rng);
		sum += std::exp(fd.logDensity(s) - q.logDensity(s));
	}
	EXPECT_NEAR(sum / N, 1.0, 0.03);
}

TEST(DualProposal, EmptyProposalIsInvalid)
{
	const CDualProposal q;
	EXPECT_FALSE(q.valid());
	EXPECT_EQ(q.logDensity({0, 0, 0}), -std::numeric_limits<double>::infinity());
}
