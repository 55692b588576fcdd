#pragma once
/** \file CLandmarkDatabase.h
 * Every landmark the front-end knows, and an approximate nearest-neighbour
 * index over all their descriptors (DescriptorIndex.h: OpenCV FLANN or our
 * best-bin-first tree, `search_index`). An
 * image's features vote for the landmarks their nearest descriptors belong
 * to (after Lowe's ratio test); the landmarks with most votes are the
 * candidates for the pose solve. Descriptors are stored once, encoded by
 * the configured DescriptorCodec (float, bytes or a projection to fewer
 * dimensions); the index and all matching work in the codec's space.
 */
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/DescriptorIndex.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/TVisualFrontEndOptions.h>
#include <libvslam/frontend/VisualLandmarkModel.h>

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
	/** Adds landmarks whose descriptors are stored codes (as landmarks()
	 * hold them, e.g. from a saved map), with one index build: codes in
	 * this database's storage are kept as they are, others re-encoded
	 * when they decode to SIFT values (float, uint8, uint4). Throws
	 * std::invalid_argument, before adding any, for projected codes of
	 * another storage (they cannot be converted) or an ID that exists. */
	void insertStored(std::vector<VisualLandmarkModel> landmarks);
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
	/** A new index over the live landmarks (after many removals). */
	void rebuildIndex();

	TVisualFrontEndOptions m_options;
	DescriptorCodec m_codec;  //!< stored descriptors (verification)
	DescriptorCodec m_searchCodec;  //!< the index's space
	std::map<int64_t, VisualLandmarkModel> m_landmarks;  // ordered: deterministic iteration
	std::unique_ptr<DescriptorIndex> m_index;
};
}  // namespace vslam
