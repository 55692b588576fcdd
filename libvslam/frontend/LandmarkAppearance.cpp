#include <libvslam/frontend/LandmarkAppearance.h>

#include <cstring>

using namespace vslam;

CVSlamMap::TLandmarkAppearance vslam::appearanceOf(const VisualLandmarkModel& lm)
{
	CVSlamMap::TLandmarkAppearance a;
	a.id = lm.id;
	for (const auto& p : lm.points) a.points.push_back({p.x, p.y, p.z});
	a.depthStd = lm.depthStd;
	const cv::Mat codes = lm.descriptors.isContinuous() ? lm.descriptors : lm.descriptors.clone();
	a.descriptorDepth = codes.depth();
	a.descriptorCols = codes.cols;
	a.descriptorBytes.assign(codes.data, codes.data + codes.total() * codes.elemSize());
	a.createdAt = lm.createdAt;
	a.createdAtOdometry = lm.createdAtOdometry.asTPose();
	a.views = lm.views;
	a.reprojectionRms = lm.reprojectionRms;
	a.recognitions = lm.recognitions;
	const auto scale = lm.scale.state();
	a.scaleInformation = scale.information;
	a.scaleWeightedSum = scale.weightedSum;
	a.scalePairsUsed = scale.pairsUsed;
	a.scalePairsRejected = scale.pairsRejected;
	return a;
}

VisualLandmarkModel vslam::landmarkOf(
	const CVSlamMap::TLandmarkAppearance& a, const TScaleTrackOptions* scaleSettings)
{
	VisualLandmarkModel lm;
	lm.id = a.id;
	for (const auto& p : a.points) lm.points.emplace_back(p.x, p.y, p.z);
	lm.depthStd = a.depthStd;
	lm.descriptors = cv::Mat(static_cast<int>(a.points.size()), a.descriptorCols, CV_MAKETYPE(a.descriptorDepth, 1));
	std::memcpy(lm.descriptors.data, a.descriptorBytes.data(), a.descriptorBytes.size());
	lm.createdAt = a.createdAt;
	lm.createdAtOdometry = mrpt::poses::CPose2D(a.createdAtOdometry);
	lm.views = a.views;
	lm.reprojectionRms = a.reprojectionRms;
	lm.recognitions = a.recognitions;
	if (scaleSettings)
		lm.scale = CLandmarkScaleTrack::resumed(
			{a.scaleInformation, a.scaleWeightedSum, a.scalePairsUsed, a.scalePairsRejected}, *scaleSettings);
	return lm;
}
