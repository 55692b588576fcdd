#pragma once
/** \file ChiSquare.h
 * Chi-square CDF and quantile for validation gates, any degrees of freedom
 * (Boost.Math: accurate to the last digits, where MRPT's chi2inv is a
 * Wilson-Hilferty approximation). */
namespace vslam
{
/** P(X <= x) for X ~ chi2(dof), dof >= 1. */
double chiSquareCdf(double x, int dof);
/** The x with chiSquareCdf(x, dof) = p, for p in (0, 1), dof >= 1. */
double chiSquareQuantile(double p, int dof);
}  // namespace vslam
