#include <libvslam/core/InputError.h>
#include <libvslam/eval/Median.h>
#include <libvslam/frontend/DescriptorMatching.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/tools/ImageSequenceStats.h>
#include <mrpt/obs/CObservationImage.h>
#include <opencv2/calib3d.hpp>

#include <algorithm>

namespace vslam
{
namespace
{
struct Frame
{
	double t;
	ImageFeatures features;
};

/** Ratio-test matches and the inliers of a fundamental matrix among them. */
std::pair<size_t, size_t> matchPair(const Frame& a, const Frame& b, double ratio)
{
	const auto matches = matchDescriptors(a.features.descriptors, b.features.descriptors, ratio);
	if (matches.size() < 8) return {matches.size(), 0};
	std::vector<cv::Point2f> pa, pb;
	for (const auto& [i, j] : matches) pa.push_back(a.features.pixels[i]), pb.push_back(b.features.pixels[j]);
	std::vector<uchar> inlier;
	cv::setRNGSeed(1);  // RANSAC: same answer run after run
	cv::findFundamentalMat(pa, pb, cv::FM_RANSAC, 1.0, 0.999, inlier);
	return {matches.size(), static_cast<size_t>(std::count(inlier.begin(), inlier.end(), 1))};
}

MatchStats summarize(const std::vector<std::pair<size_t, size_t>>& results)
{
	MatchStats s;
	s.pairs = results.size();
	std::vector<double> m, in;
	for (const auto& [matches, inliers] : results)
	{
		m.push_back(matches), in.push_back(inliers);
		s.pairsWithUnder20Inliers += inliers < 20;
	}
	s.medianMatches = median(m), s.medianInliers = median(in);
	return s;
}
}  // namespace

ImageSequenceStats computeImageSequenceStats(const std::string& rawlogFile, const Trajectory& truth,
	const CFeatureExtractor::TOptions& features, const CImageCalibration::TOptions& camera,
	const TImageSequenceStatsOptions& o)
{
	const CFeatureExtractor extractor(features);
	std::vector<Frame> frames;
	CRawlogReader reader(rawlogFile);
	RawlogStep step;
	while (reader.next(step))
	{
		for (const auto& obs : *step.sf)
		{
			const auto* img = dynamic_cast<const mrpt::obs::CObservationImage*>(obs.get());
			if (!img) continue;
			const std::string what = "rawlog '" + rawlogFile + "', entry " + std::to_string(step.entry);
			cv::Mat pixels;
			try
			{
				pixels = img->image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
			}
			catch (const std::exception& e)
			{
				throw InputError(what + ": cannot load the image: " + e.what());
			}
			const auto calibration = CImageCalibration::from(img->cameraParams, pixels.cols, pixels.rows, camera, what);
			frames.push_back({mrpt::Clock::toDouble(img->timestamp), extractor.extract(pixels, calibration)});
		}
	}
	ImageSequenceStats s;
	s.images = frames.size();
	std::vector<double> counts;
	for (const auto& f : frames)
	{
		counts.push_back(static_cast<double>(f.features.size()));
		s.featureCounts.push_back(f.features.size());
		s.imagesUnder80Features += f.features.size() < 80;
	}
	s.minFeatures = counts.empty() ? 0 : *std::min_element(counts.begin(), counts.end());
	s.medianFeatures = median(counts);

	std::vector<std::pair<size_t, size_t>> apart, revisits;
	for (size_t i = 0, j = 0; i < frames.size(); i++)
	{
		while (j < frames.size() && frames[j].t < frames[i].t + o.pairSeconds - 1e-6) j++;
		if (j < frames.size()) apart.push_back(matchPair(frames[i], frames[j], features.match_ratio));
	}
	for (size_t j = 0; j < frames.size(); j++)
	{
		const auto pj = interpolate(truth, frames[j].t, 1.0);
		if (!pj) continue;
		double best = 1e9;
		size_t bestI = frames.size();
		for (size_t i = 0; i < j && frames[j].t - frames[i].t >= o.revisitMinSeconds; i++)
		{
			const auto pi = interpolate(truth, frames[i].t, 1.0);
			if (!pi) continue;
			const double d = std::hypot(pi->x - pj->x, pi->y - pj->y), a = std::abs(se2::wrap(pi->phi - pj->phi));
			if (d <= o.revisitMaxDistance && a <= o.revisitMaxAngle && d + a < best) best = d + a, bestI = i;
		}
		if (bestI < frames.size()) revisits.push_back(matchPair(frames[bestI], frames[j], features.match_ratio));
	}
	s.apart = summarize(apart);
	s.revisits = summarize(revisits);
	return s;
}
}  // namespace vslam
