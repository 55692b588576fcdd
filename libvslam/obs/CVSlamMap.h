#pragma once
/** \file CVSlamMap.h
 * A whole vslam map, as `final_map.vslam` stores it: what the filter knows
 * of every landmark (the best particle's estimate and covariance) and what
 * the visual front-end recognizes each visual landmark by (its 3-D points,
 * their stored descriptors and bookkeeping), with the camera calibration
 * the map was built with. A later run loads it as `[vslam] prior_map_file`
 * to localize in it or to extend it.
 *
 * Plain data with no OpenCV or filter types, so the class lives in the
 * observation library: stock MRPT tools read it with LD_PRELOAD, as they
 * read the observations. Reading grows every array with the data actually
 * read (a corrupt count meets the end of the data, it cannot allocate
 * gigabytes) and validate() checks the content (finite values, unique IDs,
 * an appearance only for a visual landmark the filter knows).
 */
#include <mrpt/img/TCamera.h>
#include <mrpt/math/TPoint3D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/serialization/CSerializable.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vslam
{
class CVSlamMap : public mrpt::serialization::CSerializable
{
	DEFINE_SERIALIZABLE(CVSlamMap, vslam)

   public:
	/** One landmark as the filter holds it. */
	struct TLandmarkEstimate
	{
		uint8_t kind = 0;  //!< 0: pose (visual landmark frame), 1: point (range-bearing)
		int64_t id = -1;
		std::array<double, 3> mean{};  //!< x, y, phi (phi 0 for a point), world frame
		/** Upper triangle of the covariance, row by row: xx xy xphi yy yphi phiphi. */
		std::array<double, 6> cov{};
		uint32_t updates = 0;  //!< Kalman updates applied
		uint64_t measurements = 0;  //!< measurements the filter used
	};

	/** Descriptor storage kinds, as OpenCV depths (the front-end's codec:
	 * uint8 and uint4 are bytes, projected signed bytes, float floats). */
	enum DescriptorDepth : int32_t
	{
		kBytes = 0,
		kSignedBytes = 1,
		kFloats = 5
	};

	/** What the front-end recognizes one visual landmark by. */
	struct TLandmarkAppearance
	{
		int64_t id = -1;
		std::vector<mrpt::math::TPoint3Df> points;  //!< landmark frame, metres
		std::vector<float> depthStd;  //!< per point, relative; empty: points taken as exact
		int32_t descriptorDepth = kBytes;
		int32_t descriptorCols = 0;
		/** points.size() rows of descriptorCols values, row-major, raw bytes. */
		std::vector<uint8_t> descriptorBytes;
		double createdAt = 0;  //!< s
		mrpt::math::TPose2D createdAtOdometry;  //!< the building run's odometry frame
		int32_t views = 0;
		double reprojectionRms = 0;  //!< px
		int32_t recognitions = 0;
		/** Its scale estimate (CLandmarkScaleTrack): information and
		 * information-weighted sum of the scale error, and pairs judged. */
		double scaleInformation = 1, scaleWeightedSum = 1;
		int32_t scalePairsUsed = 0, scalePairsRejected = 0;

		size_t descriptorValueBytes() const { return descriptorDepth == kFloats ? 4 : 1; }
	};

	std::string runId;  //!< the run that wrote it
	/** The front-end's descriptor_storage the descriptors are stored in. */
	std::string descriptorStorage;
	bool hasCamera = false;
	mrpt::img::TCamera camera;  //!< the first camera image's calibration
	std::vector<TLandmarkEstimate> estimates;
	std::vector<TLandmarkAppearance> appearances;
	/** The front-end's next visual landmark ID: a run that extends the map
	 * never reuses one. */
	int64_t nextVisualLandmarkId = 1;

	/** Throws std::runtime_error naming the first inconsistency. */
	void validate() const;
};
}  // namespace vslam
