#include <libvslam/frontend/BundleAdjustment.h>

#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include <cmath>

namespace vslam::ba
{
namespace
{
Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d m;
	m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return m;
}

Eigen::Matrix3d expSO3(const Eigen::Vector3d& w)
{
	const double a = w.norm();
	if (a < 1e-12) return Eigen::Matrix3d::Identity() + skew(w);
	return Eigen::AngleAxisd(a, w / a).toRotationMatrix();
}

double huberWeight(double r, double k) { return r <= k ? 1.0 : k / r; }

double huberCost(double r, double k) { return r <= k ? 0.5 * r * r : k * (r - 0.5 * k); }

double totalCost(const Problem& p, double k)
{
	double c = 0;
	for (const auto& prior : p.priors) c += 0.5 * priorResidual(p, prior).squaredNorm();
	for (const auto& o : p.observations)
	{
		const Eigen::Vector3d Xc = p.poses[o.camera].map(p.points[o.point]);
		if (Xc.z() <= 1e-9)
		{
			c += huberCost(1e3, k);
			continue;
		}
		c += huberCost(residual(p, o).norm(), k);
	}
	return c;
}
}  // namespace

Eigen::Matrix<double, 6, 1> priorResidual(const Problem& p, const PosePrior& prior)
{
	const CameraPose& pose = p.poses[prior.camera];
	const Eigen::AngleAxisd e(pose.R * prior.pose.R.transpose());
	Eigen::Matrix<double, 6, 1> r;
	const Eigen::Vector3d rotation = e.angle() * e.axis();
	r.head<3>() = rotation / prior.sigmaRotation;
	r.tail<3>() = (pose.t - prior.pose.t) / prior.sigmaTranslation;
	return r;
}

Eigen::Matrix<double, 6, 6> priorJacobian(const Problem& p, const PosePrior& prior)
{
	Eigen::Matrix<double, 6, 6> J = Eigen::Matrix<double, 6, 6>::Zero();
	J.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() / prior.sigmaRotation;
	J.bottomLeftCorner<3, 3>() = -skew(p.poses[prior.camera].t) / prior.sigmaTranslation;
	J.bottomRightCorner<3, 3>() = Eigen::Matrix3d::Identity() / prior.sigmaTranslation;
	return J;
}

Eigen::Vector2d residual(const Problem& p, const Observation& o)
{
	const Eigen::Vector3d Xc = p.poses[o.camera].map(p.points[o.point]);
	const auto& c = p.camera;
	return {c.fx * Xc.x() / Xc.z() + c.cx - o.pixel.x(), c.fy * Xc.y() / Xc.z() + c.cy - o.pixel.y()};
}

void jacobians(
	const Problem& p, const Observation& o, Eigen::Matrix<double, 2, 6>& Jcam,
	Eigen::Matrix<double, 2, 3>& Jpoint)
{
	const CameraPose& pose = p.poses[o.camera];
	const Eigen::Vector3d Xc = pose.map(p.points[o.point]);
	const double z = Xc.z(), z2 = z * z;
	Eigen::Matrix<double, 2, 3> Jproj;
	Jproj << p.camera.fx / z, 0, -p.camera.fx * Xc.x() / z2, 0, p.camera.fy / z,
		-p.camera.fy * Xc.y() / z2;
	Jcam.leftCols<3>() = -Jproj * skew(Xc);
	Jcam.rightCols<3>() = Jproj;
	Jpoint = Jproj * pose.R;
}

CameraPose perturbed(const CameraPose& pose, const Eigen::Matrix<double, 6, 1>& d)
{
	const Eigen::Matrix3d dR = expSO3(d.head<3>());
	return {dR * pose.R, dR * pose.t + d.tail<3>()};
}

namespace
{
/** The Gauss-Newton system of a problem, cameras 1.. and points apart: A
 * and gc for the free cameras, C and gp per point, B per observation
 * (camera x point), each observation Huber-weighted; priors included. */
struct NormalEquations
{
	Eigen::MatrixXd A;
	Eigen::VectorXd gc;
	std::vector<Eigen::Matrix3d> C;
	std::vector<Eigen::Vector3d> gp;
	std::vector<Eigen::Matrix<double, 6, 3>> B;
};

NormalEquations normalEquations(const Problem& p, const TRefineOptions& opt)
{
	const int nc = static_cast<int>(p.poses.size()) - 1;
	const int np = static_cast<int>(p.points.size());
	NormalEquations eq{Eigen::MatrixXd::Zero(6 * nc, 6 * nc), Eigen::VectorXd::Zero(6 * nc),
		std::vector<Eigen::Matrix3d>(np, Eigen::Matrix3d::Zero()), std::vector<Eigen::Vector3d>(np, Eigen::Vector3d::Zero()),
		std::vector<Eigen::Matrix<double, 6, 3>>(p.observations.size())};
	for (size_t k = 0; k < p.observations.size(); k++)
	{
		const auto& o = p.observations[k];
		eq.B[k].setZero();
		if (p.poses[o.camera].map(p.points[o.point]).z() <= 1e-9) continue;
		Eigen::Matrix<double, 2, 6> Jc;
		Eigen::Matrix<double, 2, 3> Jp;
		jacobians(p, o, Jc, Jp);
		const Eigen::Vector2d r = residual(p, o);
		const double w = huberWeight(r.norm(), opt.huberPx);
		eq.C[o.point] += w * Jp.transpose() * Jp;
		eq.gp[o.point] += w * Jp.transpose() * r;
		if (o.camera == 0) continue;
		const int j = 6 * (o.camera - 1);
		eq.A.block<6, 6>(j, j) += w * Jc.transpose() * Jc;
		eq.gc.segment<6>(j) += w * Jc.transpose() * r;
		eq.B[k] = w * Jc.transpose() * Jp;
	}
	for (const auto& prior : p.priors)
	{
		if (prior.camera < 1) continue;
		const int j = 6 * (prior.camera - 1);
		const Eigen::Matrix<double, 6, 6> J = priorJacobian(p, prior);
		eq.A.block<6, 6>(j, j) += J.transpose() * J;
		eq.gc.segment<6>(j) += J.transpose() * priorResidual(p, prior);
	}
	return eq;
}

/** The problem moved by the Levenberg-Marquardt step with damping
 * \a lambda: the cameras solved on the Schur complement
 * (S = A - B C^-1 B^T over pairs of observations of the same point), then
 * each point from its own block. */
Problem dampedStep(const Problem& p, const NormalEquations& eq, double lambda)
{
	const int nc = static_cast<int>(p.poses.size()) - 1;
	const int np = static_cast<int>(p.points.size());
	std::vector<Eigen::Matrix3d> Cinv(np);
	for (int i = 0; i < np; i++)
	{
		Eigen::Matrix3d Ci = eq.C[i];
		Ci.diagonal() *= 1 + lambda;
		Ci.diagonal().array() += 1e-9;
		Cinv[i] = Ci.inverse();
	}
	Eigen::MatrixXd S = eq.A;
	S.diagonal() *= 1 + lambda;
	S.diagonal().array() += 1e-9;
	Eigen::VectorXd rhs = eq.gc;
	std::vector<std::vector<size_t>> obsOfPoint(np);
	for (size_t k = 0; k < p.observations.size(); k++)
		if (p.observations[k].camera > 0) obsOfPoint[p.observations[k].point].push_back(k);
	for (int i = 0; i < np; i++)
		for (size_t a : obsOfPoint[i])
		{
			const int ja = 6 * (p.observations[a].camera - 1);
			const Eigen::Matrix<double, 6, 3> BC = eq.B[a] * Cinv[i];
			rhs.segment<6>(ja) -= BC * eq.gp[i];
			for (size_t b : obsOfPoint[i])
			{
				const int jb = 6 * (p.observations[b].camera - 1);
				S.block<6, 6>(ja, jb) -= BC * eq.B[b].transpose();
			}
		}
	const Eigen::VectorXd dc = S.ldlt().solve(-rhs);
	Problem trial = p;
	for (int j = 0; j < nc; j++) trial.poses[j + 1] = perturbed(p.poses[j + 1], dc.segment<6>(6 * j));
	std::vector<Eigen::Vector3d> bdc(np, Eigen::Vector3d::Zero());
	for (size_t k = 0; k < p.observations.size(); k++)
	{
		const auto& o = p.observations[k];
		if (o.camera > 0) bdc[o.point] += eq.B[k].transpose() * dc.segment<6>(6 * (o.camera - 1));
	}
	for (int i = 0; i < np; i++) trial.points[i] = p.points[i] - Cinv[i] * (eq.gp[i] + bdc[i]);
	return trial;
}
}  // namespace

double refine(Problem& p, const TRefineOptions& opt)
{
	const int nc = static_cast<int>(p.poses.size()) - 1;  // free cameras
	const int np = static_cast<int>(p.points.size());
	if (nc < 1 || np == 0) return totalCost(p, opt.huberPx);
	double lambda = 1e-3;
	double cost = totalCost(p, opt.huberPx);
	for (int it = 0; it < opt.iterations; it++)
	{
		const NormalEquations eq = normalEquations(p, opt);
		for (;;)  // LM: raise lambda until the step lowers the cost
		{
			Problem trial = dampedStep(p, eq, lambda);
			const double trialCost = totalCost(trial, opt.huberPx);
			if (std::isfinite(trialCost) && trialCost < cost)
			{
				const bool converged = cost - trialCost < 1e-6 * cost;
				p = std::move(trial);
				cost = trialCost;
				lambda = std::max(1e-7, lambda / 10);
				if (converged) return cost;
				break;
			}
			lambda *= 10;
			if (lambda > 1e8) return cost;
		}
	}
	return cost;
}

bool triangulate(
	const PinholeCamera& camera, const std::vector<CameraPose>& poses,
	const std::vector<Eigen::Vector2d>& pixels, Eigen::Vector3d& point)
{
	const int n = static_cast<int>(poses.size());
	if (n < 2) return false;
	Eigen::MatrixXd M(2 * n, 4);
	for (int i = 0; i < n; i++)
	{
		Eigen::Matrix<double, 3, 4> P;
		P.leftCols<3>() = poses[i].R;
		P.col(3) = poses[i].t;
		const double x = (pixels[i].x() - camera.cx) / camera.fx;
		const double y = (pixels[i].y() - camera.cy) / camera.fy;
		M.row(2 * i) = x * P.row(2) - P.row(0);
		M.row(2 * i + 1) = y * P.row(2) - P.row(1);
	}
	const Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullV);
	const Eigen::Vector4d X = svd.matrixV().col(3);
	if (std::abs(X(3)) < 1e-12) return false;
	point = X.head<3>() / X(3);
	return point.allFinite();
}
}  // namespace vslam::ba
