#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/DescriptorMatching.h>
#include <libvslam/frontend/HeadingChange.h>
#include <libvslam/models/SE2.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace vslam;

namespace
{
Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d S;
	S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return S;
}

/** A camera closer than this to not moving at all is treated as rotating
 * only (m). */
constexpr double kStillCamera = 1e-9;

/** Bin width of the bearing-change votes, and the fine search's step. */
constexpr double kVoteBin = 0.5 * M_PI / 180;
constexpr double kSearchStep = 0.05 * M_PI / 180;

/** Slip allowed in the chord's direction beyond the two headings, rad. */
constexpr double kChordSlip = 1.0 * M_PI / 180;

/** Normalized image point of a camera-frame direction, and its derivative
 * for a derivative dp of the direction. */
Eigen::Vector2d normalized(const Eigen::Vector3d& p) { return {p.x() / p.z(), p.y() / p.z()}; }
Eigen::Vector2d normalizedDerivative(const Eigen::Vector3d& p, const Eigen::Vector3d& dp)
{
	return {(dp.x() * p.z() - p.x() * dp.z()) / (p.z() * p.z()), (dp.y() * p.z() - p.y() * dp.z()) / (p.z() * p.z())};
}
/** The prior std of the wobble angles (rad): a floor shakes a robot's
 * camera by a fraction of a degree between frames, a bump by a degree or
 * two; the prior only keeps a fit with too few matches from trading the
 * heading for a wobble. */
constexpr double kWobblePriorStd = 1.0 * M_PI / 180;

/** Gauss-Newton for theta on the arc (alpha = theta/2) and the camera's
 * wobble between the images (two small rotations perpendicular to the
 * robot's vertical), over the matches within tau of the model, chosen
 * again after each step. */
struct ArcFit
{
	double theta = 0;
	std::vector<char> inlier;
	Eigen::Matrix3d H;  //!< normal matrix of (theta, wobble 0, wobble 1), with the wobble prior
	Eigen::Vector3d gAlpha;  //!< sum of J dr/dalpha: the fit's sensitivity to the chord direction
	double sumRR = 0;
	int n = 0;
};

std::optional<ArcFit> fitOnArc(const PlanarEpipolarModel& model, const std::vector<Eigen::Vector3d>& rays1,
	const std::vector<Eigen::Vector3d>& rays2, double theta, double tau, size_t least)
{
	ArcFit f;
	f.theta = theta;
	f.inlier.assign(rays1.size(), 0);
	Eigen::Matrix3d wobble = Eigen::Matrix3d::Identity();
	Eigen::Vector2d wobbleAngles = Eigen::Vector2d::Zero();
	// The prior's information relative to a match's, whose residual std is
	// taken as half the inlier bound.
	const double priorWeight = (tau / 2) * (tau / 2) / (kWobblePriorStd * kWobblePriorStd);
	std::vector<char> previous;
	for (int iteration = 0; iteration < 30; iteration++)
	{
		// The search above held the camera level: a shake of a degree moves
		// the points by several pixels, so the first steps take matches from
		// farther off the model, and the bound narrows as the wobble is found.
		const double bound = tau * (iteration < 3 ? 4 : iteration < 6 ? 2 : 1);
		f.H = Eigen::Matrix3d::Zero();
		f.gAlpha.setZero();
		Eigen::Vector3d g = Eigen::Vector3d::Zero();
		f.sumRR = 0;
		f.n = 0;
		const EpipolarMotion m = model.motion(f.theta, f.theta / 2, wobble);
		for (size_t i = 0; i < rays1.size(); i++)
		{
			double dTheta = 0, dAlpha = 0, dWobble[2] = {0, 0};
			const double r = PlanarEpipolarModel::residual(m, rays1[i], rays2[i], &dTheta, &dAlpha, dWobble);
			f.inlier[i] = std::abs(r) <= bound;
			if (!f.inlier[i]) continue;
			const Eigen::Vector3d J(dTheta + dAlpha / 2, dWobble[0], dWobble[1]);  // theta along the arc
			f.H += J * J.transpose();
			g += J * r;
			f.gAlpha += J * dAlpha;
			f.sumRR += r * r;
			f.n++;
		}
		if (f.n < static_cast<int>(least)) return std::nullopt;
		f.H(1, 1) += priorWeight;
		f.H(2, 2) += priorWeight;
		g.tail<2>() += priorWeight * wobbleAngles;
		const Eigen::Vector3d step = -f.H.ldlt().solve(g);
		if (!step.allFinite()) return std::nullopt;
		const bool settled = f.inlier == previous && bound == tau;
		previous = f.inlier;
		if (settled && step.norm() < 1e-10) break;
		f.theta += step[0];
		wobbleAngles += step.tail<2>();
		const Eigen::Vector3d w = model.wobbleAxes().leftCols<2>() * step.tail<2>();
		wobble = wobble * Eigen::AngleAxisd(w.norm(), w.norm() > 0 ? Eigen::Vector3d(w.normalized()) : Eigen::Vector3d::UnitX())
							  .toRotationMatrix();
	}
	if (!(f.H.determinant() > 0)) return std::nullopt;
	return f;
}
}  // namespace

void CHeadingChangeEstimator::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace config;
	enabled = readBool(c, s, "enabled", enabled);
	min_inliers = readCount(c, s, "min_inliers", min_inliers, 5, 100000);
	inlier_px = readDouble(c, s, "inlier_px", inlier_px, Range::positive());
}

void CHeadingChangeEstimator::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "enabled", enabled, 30, 10,
		"Measure the heading change from each image to the camera's previous one (for [vslam_heading_change])");
	c.write(s, "min_inliers", min_inliers, 30, 10, "Feature matches that must fit the motion");
	c.write(s, "inlier_px", inlier_px, 30, 10, "Epipolar distance of an inlier [px]");
}

CHeadingChangeEstimator::CHeadingChangeEstimator(const TOptions& options, double matchRatio)
{
	m_settings.matchRatio = matchRatio;
	m_settings.minInliers = options.min_inliers;
	m_settings.inlierPx = options.inlier_px;
}

PlanarEpipolarModel::PlanarEpipolarModel(const mrpt::poses::CPose3D& mount, double chord)
	: m_Rm(mount.getRotationMatrix().asEigen()), m_tm(mount.x(), mount.y(), mount.z()), m_chord(chord)
{
	const Eigen::Vector3d vertical = m_Rm.transpose() * Eigen::Vector3d::UnitZ();
	// Any axis not along the vertical gives the first perpendicular one.
	const Eigen::Vector3d helper =
		std::abs(vertical.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
	const Eigen::Vector3d a = vertical.cross(helper).normalized();
	m_wobbleAxes.col(0) = a;
	m_wobbleAxes.col(1) = vertical.cross(a);
	m_wobbleAxes.col(2) = vertical;
}

double PlanarEpipolarModel::chordDirectionStd(double theta)
{
	return std::sqrt(theta * theta / 4 + kChordSlip * kChordSlip);
}

void PlanarEpipolarModel::cameraMotion(double theta, double alpha, Eigen::Matrix3d& R, Eigen::Vector3d& t,
	Eigen::Matrix3d* dR_dtheta, Eigen::Vector3d* dt_dtheta, Eigen::Vector3d* dt_dalpha) const
{
	const double c = std::cos(theta), s = std::sin(theta);
	Eigen::Matrix3d Rz;
	Rz << c, -s, 0, s, c, 0, 0, 0, 1;
	const Eigen::Vector3d tu(m_chord * std::cos(alpha), m_chord * std::sin(alpha), 0);
	// Robot motion U: X_robot1 = Rz X_robot2 + tu; the camera: X_robot = Rm X_cam + tm.
	R = m_Rm.transpose() * Rz * m_Rm;
	t = m_Rm.transpose() * (Rz * m_tm + tu - m_tm);
	if (dR_dtheta || dt_dtheta)
	{
		Eigen::Matrix3d dRz;
		dRz << -s, -c, 0, c, -s, 0, 0, 0, 0;
		if (dR_dtheta) *dR_dtheta = m_Rm.transpose() * dRz * m_Rm;
		if (dt_dtheta) *dt_dtheta = m_Rm.transpose() * (dRz * m_tm);
	}
	if (dt_dalpha)
		*dt_dalpha = m_Rm.transpose() * Eigen::Vector3d(-m_chord * std::sin(alpha), m_chord * std::cos(alpha), 0);
}

EpipolarMotion PlanarEpipolarModel::motion(double theta, double alpha, const Eigen::Matrix3d& wobble) const
{
	EpipolarMotion m;
	Eigen::Vector3d t, dt, dta;
	cameraMotion(theta, alpha, m.R, t, &m.dR_dtheta, &dt, &dta);
	// The wobble turns the second camera about its own centre: t stays.
	m.R = m.R * wobble;
	m.dR_dtheta = m.dR_dtheta * wobble;
	for (int k = 0; k < 2; k++) m.dR_dwobble[k] = m.R * skew(m_wobbleAxes.col(k));
	m.still = t.norm() < kStillCamera && dt.norm() < kStillCamera && dta.norm() < kStillCamera;
	if (m.still)
	{
		Eigen::Vector3d t0;
		cameraMotion(0, 0, m.R0, t0, &m.dR0_dtheta);
		return m;
	}
	if (t.norm() < kStillCamera)
	{
		// The camera passes through not moving (a turn in place through
		// theta = 0): E = 0 there, but the Sampson distance only needs E's
		// direction, whose limit is that of dt.
		t = dt.norm() >= kStillCamera ? Eigen::Vector3d(dt) : Eigen::Vector3d(dta);
		t *= kStillCamera / t.norm();
	}
	m.E = skew(t) * m.R;
	m.dE_dtheta = skew(dt) * m.R + skew(t) * m.dR_dtheta;
	m.dE_dalpha = skew(dta) * m.R;
	for (int k = 0; k < 2; k++) m.dE_dwobble[k] = skew(t) * m.dR_dwobble[k];
	m.translation = t.norm();
	return m;
}

double PlanarEpipolarModel::residual(const EpipolarMotion& m, const Eigen::Vector3d& r1, const Eigen::Vector3d& r2,
	double* dTheta, double* dAlpha, double* dWobble)
{
	if (m.still)
	{
		// A camera that only rotates: r1 against R r2 across the direction in
		// which the rotation moves the point (fixed, from theta = 0).
		const Eigen::Vector2d g0 = normalizedDerivative(m.R0 * r2, m.dR0_dtheta * r2);
		const Eigen::Vector2d across = g0.norm() > 0 ? Eigen::Vector2d(g0.normalized()) : Eigen::Vector2d(1, 0);
		const Eigen::Vector3d p = m.R * r2;
		if (dTheta) *dTheta = -normalizedDerivative(p, m.dR_dtheta * r2).dot(across);
		if (dAlpha) *dAlpha = 0;
		if (dWobble)
			for (int k = 0; k < 2; k++) dWobble[k] = -normalizedDerivative(p, m.dR_dwobble[k] * r2).dot(across);
		return (normalized(r1) - normalized(p)).dot(across);
	}
	// x1^T E x2 = 0; Sampson's first-order distance to the epipolar lines in
	// both images.
	const Eigen::Vector3d u = m.E * r2, v = m.E.transpose() * r1;
	const double a = r1.dot(u);
	const double b = u.x() * u.x() + u.y() * u.y() + v.x() * v.x() + v.y() * v.y();
	if (!(b > 0))
	{
		if (dTheta) *dTheta = 0;
		if (dAlpha) *dAlpha = 0;
		if (dWobble) dWobble[0] = dWobble[1] = 0;
		return 0;
	}
	const double sqrtB = std::sqrt(b);
	const auto derivative = [&](const Eigen::Matrix3d& dE) {
		const Eigen::Vector3d du = dE * r2, dv = dE.transpose() * r1;
		const double da = r1.dot(du);
		const double db = 2 * (u.x() * du.x() + u.y() * du.y() + v.x() * dv.x() + v.y() * dv.y());
		return da / sqrtB - 0.5 * a * db / (b * sqrtB);
	};
	if (dTheta) *dTheta = derivative(m.dE_dtheta);
	if (dAlpha) *dAlpha = derivative(m.dE_dalpha);
	if (dWobble)
		for (int k = 0; k < 2; k++) dWobble[k] = derivative(m.dE_dwobble[k]);
	return a / sqrtB;
}

namespace
{
/** The median of the votes in the densest window of three vote bins (the
 * start of the fit), if that window holds at least \a least votes. */
std::optional<double> votedHeadingChange(const std::vector<double>& votes, double maxTurn, size_t least)
{
	const int half = static_cast<int>(std::ceil(maxTurn / kVoteBin));
	std::vector<int> bins(static_cast<size_t>(2 * half + 1), 0);
	for (const double v : votes)
		if (std::abs(v) <= maxTurn) bins[static_cast<size_t>(std::lround(v / kVoteBin) + half)]++;
	int best = 0, bestCount = -1;
	for (int i = 0; i < static_cast<int>(bins.size()); i++)
	{
		int count = bins[static_cast<size_t>(i)];
		if (i > 0) count += bins[static_cast<size_t>(i - 1)];
		if (i + 1 < static_cast<int>(bins.size())) count += bins[static_cast<size_t>(i + 1)];
		if (count > bestCount) bestCount = count, best = i;
	}
	if (bestCount < static_cast<int>(least)) return std::nullopt;
	std::vector<double> window;
	for (const double v : votes)
		if (std::abs(v - (best - half) * kVoteBin) <= 1.5 * kVoteBin) window.push_back(v);
	std::nth_element(window.begin(), window.begin() + static_cast<long>(window.size() / 2), window.end());
	return window[window.size() / 2];
}

/** The heading change within three vote bins of \a theta, in steps of
 * kSearchStep, with the least truncated squared epipolar distance (each
 * ray pair's at most \a tau) on the arc. */
double leastTruncatedCostNear(const PlanarEpipolarModel& model, const std::vector<Eigen::Vector3d>& rays1,
	const std::vector<Eigen::Vector3d>& rays2, double theta, double tau)
{
	auto truncatedCost = [&](double th) {
		const EpipolarMotion m = model.motion(th, th / 2);
		double c = 0;
		for (size_t i = 0; i < rays1.size(); i++)
		{
			const double r = PlanarEpipolarModel::residual(m, rays1[i], rays2[i]);
			c += std::min(r * r, tau * tau);
		}
		return c;
	};
	double bestTheta = theta, bestCost = truncatedCost(theta);
	for (double d = -3 * kVoteBin; d <= 3 * kVoteBin + 1e-12; d += kSearchStep)
	{
		const double c = truncatedCost(theta + d);
		if (c < bestCost) bestCost = c, bestTheta = theta + d;
	}
	return bestTheta;
}
}  // namespace

std::optional<HeadingChangeEstimate> vslam::estimateHeadingChange(const ImageFeatures& first,
	const ImageFeatures& second, const mrpt::poses::CPose3D& mount, double chord, const THeadingEstimationOptions& s)
{
	const size_t least = static_cast<size_t>(std::max(2, s.minInliers));
	if (first.size() < least || second.size() < least) return std::nullopt;
	const auto matches = matchDescriptors(second.descriptors, first.descriptors, s.matchRatio);
	if (matches.size() < least) return std::nullopt;

	const PlanarEpipolarModel model(mount, chord);
	const Eigen::Matrix3d Rm = mount.getRotationMatrix().asEigen();
	const double focal = std::sqrt(second.camera.fx * second.camera.fy);
	std::vector<Eigen::Vector3d> rays1, rays2;
	std::vector<double> votes;
	rays1.reserve(matches.size());
	rays2.reserve(matches.size());
	votes.reserve(matches.size());
	for (const auto& [inSecond, inFirst] : matches)
	{
		const cv::Point3d a = first.camera.ray(first.pixels[static_cast<size_t>(inFirst)]);
		const cv::Point3d b = second.camera.ray(second.pixels[static_cast<size_t>(inSecond)]);
		rays1.emplace_back(a.x, a.y, a.z);
		rays2.emplace_back(b.x, b.y, b.z);
		// A point at bearing phi from the first pose lies at phi - theta from
		// the second (exactly so for distant points).
		const Eigen::Vector3d v1 = Rm * rays1.back(), v2 = Rm * rays2.back();
		votes.push_back(se2::wrap(std::atan2(v1.y(), v1.x()) - std::atan2(v2.y(), v2.x())));
	}

	const auto voted = votedHeadingChange(votes, s.maxTurn, least);
	if (!voted) return std::nullopt;
	// The votes ignore parallax, the model does not.
	const double tau = s.inlierPx / focal;
	double theta = leastTruncatedCostNear(model, rays1, rays2, *voted, tau);
	const auto fit = fitOnArc(model, rays1, rays2, theta, tau, least);
	if (!fit) return std::nullopt;
	theta = fit->theta;
	const std::vector<char>& inlier = fit->inlier;
	if (!(std::abs(theta) <= s.maxTurn)) return std::nullopt;
	// Each inlier's bearing change can differ from the heading change only by
	// parallax, at most the camera's translation over the nearest depth a
	// scene point may have: a fit beyond that is of another motion (a slip
	// odometry did not see, near a surface).
	Eigen::Matrix3d R;
	Eigen::Vector3d t;
	model.cameraMotion(theta, theta / 2, R, t);
	std::vector<double> offsets;
	for (size_t i = 0; i < rays1.size(); i++)
		if (inlier[i]) offsets.push_back(std::abs(se2::wrap(votes[i] - theta)));
	std::nth_element(offsets.begin(), offsets.begin() + static_cast<long>(offsets.size() / 2), offsets.end());
	if (offsets[offsets.size() / 2] > std::atan(t.norm() / s.minDepth) + kVoteBin) return std::nullopt;
	// The fit's own variance, plus the chord direction's: a chord off the
	// arc by delta moves the fitted parameters by -H^-1 g_alpha delta, with
	// delta's prior spread (a "consider" parameter: the images measure the
	// direction of a few centimetres of travel too poorly to trust their
	// own estimate of it).
	const Eigen::Matrix3d Hinv = fit->H.inverse();
	const double variance = fit->sumRR / std::max(1, fit->n - 3);  // normalized image units^2
	const double sensitivity = (Hinv * fit->gAlpha)[0];
	const double sigmaAlpha = PlanarEpipolarModel::chordDirectionStd(theta);
	HeadingChangeEstimate e;
	e.dphi = se2::wrap(theta);
	e.inliers = fit->n;
	e.matches = static_cast<int>(matches.size());
	e.rmsPx = std::sqrt(fit->sumRR / fit->n) * focal;
	e.stdDphi = std::sqrt(variance * Hinv(0, 0) + sensitivity * sensitivity * sigmaAlpha * sigmaAlpha);
	return e;
}
