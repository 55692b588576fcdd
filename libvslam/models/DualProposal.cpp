#include <libvslam/models/DualProposal.h>
#include <libvslam/models/Gaussian.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>

namespace vslam
{
namespace
{
Eigen::Vector2d rotate(double phi, const Eigen::Vector2d& v)
{
	const double c = std::cos(phi), s = std::sin(phi);
	return {c * v[0] - s * v[1], s * v[0] + c * v[1]};
}

double headingLogDensity(const HeadingPrior& h, double phi)
{
	if (h.uniform) return -std::log(2.0 * M_PI);
	const double e = se2::wrap(phi - h.mean);
	return -0.5 * (e * e) / (h.std * h.std) -
		std::log(h.std * std::sqrt(2.0 * M_PI));
}

template <class... Ts>
struct Overloaded : Ts...
{
	using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;
}  // namespace

PoseGaussianProposal makePoseGaussianProposal(
	const se2::Pose& mean, const Eigen::Matrix3d& cov)
{
	PoseGaussianProposal p;
	p.mean = mean;
	p.cov = cov;
	const Eigen::LLT<Eigen::Matrix3d> llt(cov);
	if (llt.info() != Eigen::Success) return p;
	p.L = llt.matrixL();
	const double d = p.L(0, 0) * p.L(1, 1) * p.L(2, 2);
	p.logNorm = -0.5 * (2.0 * std::log(d) + 3.0 * std::log(2.0 * M_PI));
	p.valid = std::isfinite(p.logNorm);
	return p;
}

void PointRangeBearingProposal::positionGivenHeading(
	double phi, Eigen::Vector2d& mean, Eigen::Matrix2d& cov) const
{
	const double a = phi + sensorPose.phi + bearing;
	const double c = std::cos(a), s = std::sin(a);
	const Eigen::Vector2d sensorXY = landmark - range * Eigen::Vector2d(c, s);
	mean = sensorXY - rotate(phi, {sensorPose.x, sensorPose.y});
	Eigen::Matrix2d G;  // d(-r (cos a, sin a)) / d(r, b)
	G << -c, range * s,  //
		-s, -range * c;
	cov = landmarkCov + G * rangeBearingCov * G.transpose();
}

bool CDualProposal::valid() const
{
	return std::visit(
		Overloaded{
			[](const std::monostate&) { return false; },
			[](const PoseGaussianProposal& p) { return p.valid; },
			[](const PointRangeBearingProposal& p) {
				return p.range > 0 && (p.heading.uniform || p.heading.std > 0);
			}},
		m_p);
}

se2::Pose CDualProposal::sample(mrpt::random::CRandomGenerator& rng) const
{
	return std::visit(
		Overloaded{
			[](const std::monostate&) -> se2::Pose {
				throw std::logic_error("sampling an empty dual proposal");
			},
			[&rng](const PoseGaussianProposal& p) {
				const Eigen::Vector3d n(
					rng.drawGaussian1D_normalized(),
					rng.drawGaussian1D_normalized(),
					rng.drawGaussian1D_normalized());
				const Eigen::Vector3d d = p.L * n;
				return se2::Pose{
					p.mean.x + d[0], p.mean.y + d[1],
					se2::wrap(p.mean.phi + d[2])};
			},
			[&rng](const PointRangeBearingProposal& p) {
				const double phi = p.heading.uniform
					? rng.drawUniform(-M_PI, M_PI)
					: se2::wrap(
						  p.heading.mean +
						  p.heading.std * rng.drawGaussian1D_normalized());
				Eigen::Vector2d mean;
				Eigen::Matrix2d cov;
				p.positionGivenHeading(phi, mean, cov);
				const Eigen::Matrix2d L = cov.llt().matrixL();
				const Eigen::Vector2d n(
					rng.drawGaussian1D_normalized(),
					rng.drawGaussian1D_normalized());
				const Eigen::Vector2d xy = mean + L * n;
				return se2::Pose{xy[0], xy[1], phi};
			}},
		m_p);
}

double CDualProposal::logDensity(const se2::Pose& s) const
{
	return std::visit(
		Overloaded{
			[](const std::monostate&) {
				return -std::numeric_limits<double>::infinity();
			},
			[&s](const PoseGaussianProposal& p) {
				const Eigen::Vector3d d = se2::difference(s, p.mean);
				const Eigen::Vector3d y =
					p.L.triangularView<Eigen::Lower>().solve(d);
				return p.logNorm - 0.5 * y.squaredNorm();
			},
			[&s](const PointRangeBearingProposal& p) {
				Eigen::Vector2d mean;
				Eigen::Matrix2d cov;
				p.positionGivenHeading(s.phi, mean, cov);
				const Eigen::Vector2d e(s.x - mean[0], s.y - mean[1]);
				return headingLogDensity(p.heading, s.phi) +
					evaluateGaussian(e, cov).logDensity;
			}},
		m_p);
}

Eigen::Matrix2d CDualProposal::positionSpread() const
{
	return std::visit(
		Overloaded{
			[](const std::monostate&) -> Eigen::Matrix2d {
				return Eigen::Matrix2d::Identity() * 1e12;
			},
			[](const PoseGaussianProposal& p) -> Eigen::Matrix2d {
				return p.cov.topLeftCorner<2, 2>();
			},
			[](const PointRangeBearingProposal& p) -> Eigen::Matrix2d {
				if (p.heading.uniform)
				{
					// Points on a circle of radius rho: var = rho^2 / 2.
					const double rho = p.range +
						std::hypot(p.sensorPose.x, p.sensorPose.y);
					return Eigen::Matrix2d::Identity() * (rho * rho / 2);
				}
				Eigen::Vector2d mean;
				Eigen::Matrix2d cov;
				p.positionGivenHeading(p.heading.mean, mean, cov);
				// Add the spread that the heading's uncertainty induces.
				const double eps = 1e-6;
				Eigen::Vector2d mean2;
				Eigen::Matrix2d unused;
				p.positionGivenHeading(p.heading.mean + eps, mean2, unused);
				const Eigen::Vector2d J = (mean2 - mean) / eps;
				return cov + J * J.transpose() * p.heading.std * p.heading.std;
			}},
		m_p);
}

}  // namespace vslam
