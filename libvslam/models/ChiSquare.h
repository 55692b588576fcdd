#pragma once
/** \file ChiSquare.h
 * Exact chi-square CDF and quantile for 1..3 degrees of freedom (closed
 * forms), used for validation gates. MRPT's chi2inv is a Wilson-Hilferty
 * approximation. */
namespace vslam
{
/** P(X <= x) for X ~ chi2(dof), dof in 1..3. */
double chiSquareCdf(double x, int dof);
/** The x with chiSquareCdf(x, dof) = p, for p in (0, 1), dof in 1..3. */
double chiSquareQuantile(double p, int dof);
}  // namespace vslam
