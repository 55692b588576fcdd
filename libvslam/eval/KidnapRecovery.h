#pragma once
/** \file KidnapRecovery.h
 * When a filter has found itself again after a kidnap: the first time from
 * which the position error stays within a bound for a hold time (the
 * evaluation's: within 0.3 m for 5 s, recovered if that starts within 10 s
 * of the kidnap). */
#include <optional>
#include <vector>

namespace vslam
{
struct RecoveryCriterion
{
	double within = 0.3;  //!< m
	double hold = 5.0;  //!< s the error must stay within
};

/** Seconds from \a kidnapTime until the error (\a errors at \a times,
 * increasing) stays within the bound for the hold time: every sample in
 * [t, t + hold) within it, and data reaching t + hold. nullopt if never. */
std::optional<double> recoveryTime(const std::vector<double>& times, const std::vector<double>& errors,
	double kidnapTime, const RecoveryCriterion& criterion = {});
}  // namespace vslam
