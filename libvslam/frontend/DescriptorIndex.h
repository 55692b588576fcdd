#pragma once
/** \file DescriptorIndex.h
 * Approximate nearest-neighbour search over the landmark database's
 * descriptors, in the search codec's space (DescriptorCodec.h). Every row
 * belongs to one landmark; a query gets its two nearest rows of landmarks
 * not removed. Removal is lazy: searches skip removed rows until the owner
 * (CLandmarkDatabase) rebuilds the index, which it does once
 * removedRows() passes half of rows().
 *
 * Back-ends (`[vslam_landmark_database] search_index`):
 *  - flann (FlannDescriptorIndex.h): OpenCV FLANN randomized k-d trees
 *    searched with a bounded number of leaf checks, so a query costs about
 *    the same whatever the map's size;
 *  - bbf (BestBinFirstDescriptorIndex.h): k-d trees with leaf buckets,
 *    best bin first with a bounded number of codes compared.
 * The public methods are non-virtual and keep the row bookkeeping; the
 * back-ends implement the protected virtuals.
 */
#include <opencv2/core.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <string>
#include <vector>

namespace vslam
{
class DescriptorCodec;

/** Which index, and how much of it a query searches. */
struct TDescriptorSearchOptions
{
	/** "flann" (OpenCV FLANN randomized k-d trees, bounded checks: cost per
	 * query nearly independent of the map size) or "bbf" (k-d trees with leaf
	 * buckets searched best bin first, a bounded number of codes compared). */
	std::string index = "flann";
	int checks = 32;  //!< flann: leaves checked per query and level
	int bbf_compared = 128;  //!< bbf: codes compared per query and level (whole leaves of 8)
};

/** A query's nearest rows, nearest first; dist are squared L2. */
struct NearestLandmarkRows
{
	int count = 0;
	int64_t owner[2] = {0, 0};
	float dist[2] = {0, 0};
};

class DescriptorIndex
{
   public:
	/** An index over codes of `codec` (which must outlive it). */
	explicit DescriptorIndex(const DescriptorCodec& codec) : m_codec(codec) {}
	virtual ~DescriptorIndex() = default;

	/** The back-end `search.index` names, over codes of `codec` (which
	 * must outlive the index). */
	static std::unique_ptr<DescriptorIndex> create(const TDescriptorSearchOptions& search, const DescriptorCodec& codec);

	/** Adds a landmark's descriptors (N x 128 SIFT, CV_32F) as N rows. */
	void add(int64_t owner, const cv::Mat& siftDescriptors);
	/** Adds many landmarks at once, from their stored codes (as
	 * DescriptorCodec::encode() gives them, decoded here one landmark at a
	 * time): one build instead of one per landmark (a rebuild, a loaded map). */
	void addStored(const std::vector<std::pair<int64_t, cv::Mat>>& ownedCodes);
	/** Every row of `owner` is skipped from now on. */
	void remove(int64_t owner);
	/** For each row of `queries` (the codec's matching space, CV_32F). */
	std::vector<NearestLandmarkRows> twoNearest(const cv::Mat& queries) const;

	size_t rows() const { return m_removed.size(); }
	size_t removedRows() const { return m_removedRows; }
	/** Memory held: codes, bookkeeping and the search structure. */
	size_t bytes() const;

   protected:
	/** The two nearest live rows seen so far, offered by the back-end
	 * (removed rows and rows offered again are ignored). */
	class TwoNearestLiveRows
	{
	   public:
		explicit TwoNearestLiveRows(const std::vector<char>& removed) : m_removed(removed) {}
		void offer(size_t row, float dist);
		size_t count() const { return m_count; }
		size_t row(int i) const { return m_row[i]; }
		float dist(int i) const { return m_dist[i]; }
		float worstDist() const { return m_count == 2 ? m_dist[1] : std::numeric_limits<float>::max(); }

	   private:
		const std::vector<char>& m_removed;
		size_t m_count = 0;
		size_t m_row[2] = {0, 0};
		float m_dist[2] = {0, 0};
	};

	/** Rows firstRow.. were appended, one per row of `indexRows` (the
	 * codec's indexRows() of their SIFT descriptors). */
	virtual void doAdd(size_t firstRow, const cv::Mat& indexRows) = 0;
	/** Fills one TwoNearestLiveRows per query (constructed with removed()). */
	virtual void doSearch(const cv::Mat& queries, std::vector<TwoNearestLiveRows>& out) const = 0;
	virtual size_t doBytes() const = 0;

	const std::vector<char>& removed() const { return m_removed; }
	bool anyRemoved() const { return m_removedRows > 0; }

   private:
	const DescriptorCodec& m_codec;
	/** Each add()'s rows are one block of one landmark: (first row, owner),
	 * in row order, so a row's owner costs a binary search and no memory
	 * per row. */
	std::vector<std::pair<size_t, int64_t>> m_blocks;
	int64_t ownerOf(size_t row) const;
	std::vector<char> m_removed;  //!< the row's landmark was removed (read per row searched)
	size_t m_removedRows = 0;
};
}  // namespace vslam
