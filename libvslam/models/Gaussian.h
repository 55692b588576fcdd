#pragma once
/** \file Gaussian.h
 * Small-Gaussian helpers for 1..3-dimensional measurement and pose spaces,
 * on fixed-capacity Eigen types (no heap allocation in the hot loop). */
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>

namespace vslam
{
/** A vector or matrix of dimension up to 3, sized at run time. */
using VecN = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
using MatN = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;

/** Result of evaluating N(e; 0, S). */
struct GaussianEval
{
	double logDensity = -std::numeric_limits<double>::infinity();
	/** Squared Mahalanobis distance e^T S^-1 e (the NIS for innovations). */
	double mahalanobis2 = std::numeric_limits<double>::infinity();
	bool valid = false;  //!< false if S was not positive definite
};

/** log N(e; 0, S) and e^T S^-1 e, via a Cholesky factorization. */
template <class VEC, class MAT>
GaussianEval evaluateGaussian(const VEC& e, const MAT& S)
{
	GaussianEval out;
	const Eigen::LLT<Eigen::Matrix<
		double, MAT::RowsAtCompileTime, MAT::ColsAtCompileTime, 0,
		MAT::MaxRowsAtCompileTime, MAT::MaxColsAtCompileTime>>
		llt(S);
	if (llt.info() != Eigen::Success) return out;
	const auto& L = llt.matrixL();
	const auto y = L.solve(e);
	out.mahalanobis2 = y.squaredNorm();
	double logDet = 0;
	for (int i = 0; i < S.rows(); i++)
		logDet += 2.0 * std::log(llt.matrixLLT()(i, i));
	out.logDensity = -0.5 * (out.mahalanobis2 + logDet +
							 S.rows() * std::log(2.0 * M_PI));
	out.valid = true;
	return out;
}

/** log(exp(a) + exp(b)) without overflow. */
inline double logSumExp(double a, double b)
{
	if (a == -std::numeric_limits<double>::infinity()) return b;
	if (b == -std::numeric_limits<double>::infinity()) return a;
	const double m = std::max(a, b);
	return m + std::log(std::exp(a - m) + std::exp(b - m));
}

}  // namespace vslam
