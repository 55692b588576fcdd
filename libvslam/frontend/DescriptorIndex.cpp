#include <libvslam/frontend/BestBinFirstDescriptorIndex.h>
#include <libvslam/frontend/DescriptorIndex.h>
#include <libvslam/frontend/FlannDescriptorIndex.h>

#include <algorithm>
#include <iterator>
#include <stdexcept>

using namespace vslam;

namespace
{
/** FLANN's randomized k-d trees per index level: more trees found no more
 * recognitions for their search time. */
constexpr int kFlannTrees = 1;
}  // namespace

std::unique_ptr<DescriptorIndex> DescriptorIndex::create(const TDescriptorSearchOptions& search, const DescriptorCodec& codec)
{
	if (search.index == "flann") return std::make_unique<FlannDescriptorIndex>(codec, kFlannTrees, search.checks);
	if (search.index == "bbf") return std::make_unique<BestBinFirstDescriptorIndex>(codec, search.bbf_compared);
	throw std::invalid_argument("unknown search_index '" + search.index + "' (flann | bbf)");
}

void DescriptorIndex::add(int64_t owner, const cv::Mat& siftDescriptors)
{
	if (siftDescriptors.rows == 0) return;
	const size_t first = rows();
	m_blocks.emplace_back(first, owner);
	m_removed.insert(m_removed.end(), static_cast<size_t>(siftDescriptors.rows), 0);
	doAdd(first, m_codec.indexRows(siftDescriptors));
}

void DescriptorIndex::addStored(const std::vector<std::pair<int64_t, cv::Mat>>& ownedCodes)
{
	const size_t first = rows();
	// One landmark at a time: its index rows are small, the SIFT values of
	// a whole map would not be.
	std::vector<cv::Mat> blocks;
	for (const auto& [owner, codes] : ownedCodes)
	{
		if (codes.rows == 0) continue;
		m_blocks.emplace_back(rows(), owner);
		m_removed.insert(m_removed.end(), static_cast<size_t>(codes.rows), 0);
		blocks.push_back(m_codec.indexRows(DescriptorCodec::decode(codes)));
	}
	if (blocks.empty()) return;
	cv::Mat all;
	cv::vconcat(blocks, all);
	doAdd(first, all);
}

void DescriptorIndex::remove(int64_t owner)
{
	for (size_t b = 0; b < m_blocks.size(); b++)
	{
		if (m_blocks[b].second != owner) continue;
		const size_t end = b + 1 < m_blocks.size() ? m_blocks[b + 1].first : rows();
		for (size_t i = m_blocks[b].first; i < end; i++)
			if (!m_removed[i])
			{
				m_removed[i] = 1;
				m_removedRows++;
			}
	}
}

int64_t DescriptorIndex::ownerOf(size_t row) const
{
	const auto after = std::upper_bound(m_blocks.begin(), m_blocks.end(), row,
		[](size_t r, const std::pair<size_t, int64_t>& block) { return r < block.first; });
	return std::prev(after)->second;
}

std::vector<NearestLandmarkRows> DescriptorIndex::twoNearest(const cv::Mat& queries) const
{
	std::vector<TwoNearestLiveRows> found(static_cast<size_t>(queries.rows), TwoNearestLiveRows(m_removed));
	if (queries.rows > 0 && rows() > m_removedRows) doSearch(queries, found);
	std::vector<NearestLandmarkRows> out(found.size());
	for (size_t q = 0; q < found.size(); q++)
	{
		out[q].count = static_cast<int>(found[q].count());
		for (int i = 0; i < out[q].count; i++)
		{
			out[q].owner[i] = ownerOf(found[q].row(i));
			out[q].dist[i] = found[q].dist(i);
		}
	}
	return out;
}

size_t DescriptorIndex::bytes() const
{
	return m_blocks.capacity() * sizeof(m_blocks[0]) + m_removed.capacity() + doBytes();
}

void DescriptorIndex::TwoNearestLiveRows::offer(size_t row, float dist)
{
	if (m_removed[row]) return;
	if ((m_count > 0 && m_row[0] == row) || (m_count > 1 && m_row[1] == row)) return;  // offered again
	if (m_count == 0 || dist < m_dist[0])
	{
		m_row[1] = m_row[0], m_dist[1] = m_dist[0];
		m_row[0] = row, m_dist[0] = dist;
	}
	else if (m_count == 1 || dist < m_dist[1])
		m_row[1] = row, m_dist[1] = dist;
	else
		return;
	m_count = std::min<size_t>(m_count + 1, 2);
}
