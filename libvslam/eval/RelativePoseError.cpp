#include <libvslam/core/InputError.h>
#include <libvslam/eval/RelativePoseError.h>
#include <libvslam/eval/TrajectoryAssociation.h>

#include <cmath>

namespace vslam
{
RpeStats computeRpe(const Trajectory& estimate, const Trajectory& groundTruth, const TRpeOptions& o)
{
	if (!(o.delta > 0)) throw InputError("the relative-error window must be positive");
	const std::vector<AssociatedPose> pairs = associate(estimate, groundTruth, o.maxGap);
	const bool byTime = o.window == TRpeOptions::Window::Time;
	// The true distance travelled up to each pose, and where each pose lies
	// along the window's axis (its time, or that distance).
	std::vector<double> travelledTo(pairs.size(), 0.0), along(pairs.size(), 0.0);
	for (size_t i = 0; i < pairs.size(); i++)
	{
		if (byTime && !std::isfinite(pairs[i].t))
			throw InputError("a relative error over a time window needs an estimate with timestamps");
		if (i > 0)
			travelledTo[i] = travelledTo[i - 1] +
				std::hypot(pairs[i].truth.x - pairs[i - 1].truth.x, pairs[i].truth.y - pairs[i - 1].truth.y);
		along[i] = byTime ? pairs[i].t : travelledTo[i];
	}
	std::vector<double> translation, rotation;
	double travelled = 0;
	size_t j = 0;
	for (size_t i = 0; i < pairs.size(); i++)
	{
		if (j <= i) j = i + 1;
		// (A window of 20 samples of 0.1 s must not miss by a rounding error.)
		while (j < pairs.size() && along[j] - along[i] < o.delta * (1 - 1e-9)) j++;
		if (j >= pairs.size()) break;
		if (byTime && along[j] - along[i] > o.delta + o.maxGap) continue;  // across a gap
		const se2::Pose trueMotion = se2::between(pairs[i].truth, pairs[j].truth);
		const se2::Pose estimatedMotion = se2::between(pairs[i].estimate, pairs[j].estimate);
		const se2::Pose error = se2::between(trueMotion, estimatedMotion);
		translation.push_back(std::hypot(error.x, error.y));
		rotation.push_back(std::abs(se2::wrap(error.phi)));
		travelled += travelledTo[j] - travelledTo[i];
	}
	RpeStats s;
	s.translation = summarizeErrors(translation);
	s.rotation = summarizeErrors(rotation);
	s.meanTravelled = translation.empty() ? 0 : travelled / double(translation.size());
	return s;
}
}  // namespace vslam
