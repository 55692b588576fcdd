#pragma once
/** \file CLandmarkDatabase.h
 * Every landmark the front-end knows, and an approximate nearest-neighbour
 * index (nanoflann k-d tree, incremental) over all their descriptors. An
 * image's features vote for the landmarks their nearest descriptors belong
 * to (after Lowe's ratio test); the landmarks with most votes are the
 * candidates for the pose solve. Descriptors are stored once, encoded by
 * the configured DescriptorCodec (float, bytes or a projection to fewer
 * dimensions); the tree and all matching work in the codec's space.
 */
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/TVisualFrontEndOptions.h>
#include <libvslam/frontend/VisualLandmarkModel.h>
#include <nanoflann.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace vslam
{
class CLandmarkDatabase
{
   public:
	explicit CLandmarkDatabase(const TVisualFrontEndOptions& options);
	~CLandmarkDatabase();
	CLandmarkDatabase(const CLandmarkDatabase&) = delete;
	CLandmarkDatabase& operator=(const CLandmarkDatabase&) = delete;

	/** Adds a landmark (its ID must be new), encoding its SIFT descriptors. */
	void insert(VisualLandmarkModel landmark);
	void remove(int64_t id);

	VisualLandmarkModel* find(int64_t id);
	const VisualLandmarkModel* find(int64_t id) const;
	size_t size() const { return m_landmarks.size(); }
	const std::map<int64_t, VisualLandmarkModel>& landmarks() const { return m_landmarks; }

	struct Candidate
	{
		int64_t id = 0;
		int votes = 0;
	};
	/** Landmarks with at least recognition_min_votes votes from the image's
	 * features (`image.codes`, see encode()), most votes first, at most
	 * recognition_max_candidates. */
	std::vector<Candidate> candidates(const ImageFeatures& image) const;

	/** Sets image.codes and image.searchCodes: its descriptors in the
	 * matching and the search space. */
	void encode(ImageFeatures& image) const
	{
		image.codes = m_codec.toMatchingSpace(image.descriptors);
		image.searchCodes = m_searchCodec.toMatchingSpace(image.descriptors);
	}
	const DescriptorCodec& codec() const { return m_codec; }

	/** Bytes held per landmark (points, descriptors, fields) and by the
	 * search index. */
	size_t landmarkBytes() const;
	size_t indexBytes() const;

   private:
	/** nanoflann's view of the stored descriptors: point i is row
	 * m_rows[i] of landmark m_owner[i]. */
	struct Store
	{
		/** Search codes, one block per landmark (kept alive here until the
		 * index is rebuilt): signed bytes of the projection, or floats. */
		std::vector<const void*> rows;
		std::vector<int64_t> owner;
		std::vector<cv::Mat> blocks;
		bool bytes = true;
		size_t kdtree_get_point_count() const { return rows.size(); }
		float kdtree_get_pt(size_t i, size_t d) const
		{
			return bytes ? DescriptorCodec::kProjectedStep * static_cast<const int8_t*>(rows[i])[d]
						 : static_cast<const float*>(rows[i])[d];
		}
		template <class BBox>
		bool kdtree_get_bbox(BBox&) const
		{
			return false;
		}
	};
	using Index = nanoflann::KDTreeSingleIndexDynamicAdaptor<nanoflann::L2_Simple_Adaptor<float, Store>, Store, -1>;

	void rebuildIndex();
	void addToStore(int64_t id, const cv::Mat& siftOrCodes);

	TVisualFrontEndOptions m_options;
	DescriptorCodec m_codec;  //!< stored descriptors (verification)
	DescriptorCodec m_searchCodec;  //!< the k-d tree's space
	std::map<int64_t, VisualLandmarkModel> m_landmarks;  // ordered: deterministic iteration
	Store m_store;
	std::unique_ptr<Index> m_index;
	size_t m_removedRows = 0;
};
}  // namespace vslam
