#include <libvslam/frontend/KdTreeDescriptorIndex.h>

using namespace vslam;

namespace
{
const nanoflann::KDTreeSingleIndexAdaptorParams kLeafSize(10);

/** nanoflann's result-set interface over TwoNearestLiveRows. */
template <class Nearest>
class ResultSet
{
   public:
	using DistanceType = float;
	using IndexType = uint32_t;
	explicit ResultSet(Nearest& nearest) : m_nearest(nearest) {}
	size_t size() const { return m_nearest.count(); }
	bool full() const { return m_nearest.count() == 2; }
	float worstDist() const { return m_nearest.worstDist(); }
	bool addPoint(float dist, uint32_t row)
	{
		m_nearest.offer(row, dist);
		return true;
	}

   private:
	Nearest& m_nearest;
};
}  // namespace

KdTreeDescriptorIndex::KdTreeDescriptorIndex(const DescriptorCodec& codec, double eps) : DescriptorIndex(codec), m_eps(eps)
{
	m_store.bytes = codec.kind() == DescriptorCodec::Kind::Projected;
	m_tree = std::make_unique<Tree>(static_cast<size_t>(codec.dims()), m_store, kLeafSize);
}

KdTreeDescriptorIndex::~KdTreeDescriptorIndex() = default;

void KdTreeDescriptorIndex::doAdd(size_t firstRow, const cv::Mat& indexRows)
{
	m_store.blocks.push_back(indexRows);
	const cv::Mat& block = m_store.blocks.back();
	for (int r = 0; r < block.rows; r++) m_store.rows.push_back(block.ptr(r));
	m_tree->addPoints(static_cast<uint32_t>(firstRow), static_cast<uint32_t>(m_store.rows.size() - 1));
}

void KdTreeDescriptorIndex::doSearch(const cv::Mat& queries, std::vector<TwoNearestLiveRows>& out) const
{
	const nanoflann::SearchParams params(32, static_cast<float>(m_eps));
	for (int q = 0; q < queries.rows; q++)
	{
		ResultSet<TwoNearestLiveRows> result(out[q]);
		m_tree->findNeighbors(result, queries.ptr<float>(q), params);
	}
}

size_t KdTreeDescriptorIndex::doBytes() const
{
	size_t b = m_store.rows.capacity() * sizeof(void*);
	for (const auto& block : m_store.blocks) b += block.total() * block.elemSize();
	for (const auto& sub : m_tree->getAllIndices())
		b += sub.pool.usedMemory + sub.pool.wastedMemory + sub.vAcc.capacity() * sizeof(uint32_t);
	return b;
}
