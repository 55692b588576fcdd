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
#include <libvslam/frontend/VisualLandmarkModel.h>
#include <mrpt/config/CLoadableOptions.h>

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace vslam
{
class CLandmarkDatabase
{
   public:
	/** INI section [vslam_landmark_database]: how descriptors are stored and
	 * searched, which landmarks become candidates, and the map's bounds. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_landmark_database";

		TDescriptorSearchOptions search;  //!< INI keys search_index, search_checks, search_bbf_compared
		/** The k-d tree votes in a random projection of the descriptors to this
		 * many dimensions (signed bytes; 128: no projection). Candidates are
		 * then verified with the stored descriptors. */
		int search_dims = 16;
		/** How descriptors are stored and matched (DescriptorCodec.h): float,
		 * uint8 (128 bytes), uint4 (64 bytes, square-root scale) or projected
		 * (descriptor_dims signed bytes). */
		std::string descriptor_storage = "uint8";
		int descriptor_dims = 32;
		/** A landmark is a candidate when this many image features vote for it. */
		int min_votes = 10;
		int max_candidates = 5;  //!< candidates tried per image
		/** Most landmarks kept (0: no limit); beyond it the least useful go. */
		int max_landmarks = 0;
		/** A landmark expected in view (its frame within the camera's reach)
		 * but not recognized this many times in a row is removed (0: never). */
		int prune_after_misses = 0;

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	/** `matchRatio`: the features' ratio test, for the candidates' votes. */
	CLandmarkDatabase(const TOptions& options, double matchRatio);
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
	/** Landmarks with at least min_votes votes from the image's features
	 * (`image.codes`, see encode()), most votes first, at most
	 * max_candidates. */
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

	TOptions m_options;
	double m_matchRatio;
	DescriptorCodec m_codec;  //!< stored descriptors (verification)
	DescriptorCodec m_searchCodec;  //!< the index's space
	std::map<int64_t, VisualLandmarkModel> m_landmarks;  // ordered: deterministic iteration
	std::unique_ptr<DescriptorIndex> m_index;
};
}  // namespace vslam
