#include <libvslam/frontend/CLandmarkDatabase.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

using namespace vslam;

CLandmarkDatabase::CLandmarkDatabase(const TVisualFrontEndOptions& options)
	: m_options(options),
	  m_codec(DescriptorCodec::parse(options.descriptor_storage), options.descriptor_dims),
	  m_searchCodec(options.search_dims < 128 ? DescriptorCodec::Kind::Projected : DescriptorCodec::Kind::Float,
		  options.search_dims)
{
	rebuildIndex();
}

CLandmarkDatabase::~CLandmarkDatabase() = default;

void CLandmarkDatabase::rebuildIndex()
{
	m_store = Store();
	m_store.bytes = m_searchCodec.kind() == DescriptorCodec::Kind::Projected;
	for (const auto& [id, lm] : m_landmarks) addToStore(id, DescriptorCodec::decode(lm.descriptors));
	m_removedRows = 0;
	m_index = std::make_unique<Index>(m_searchCodec.dims(), m_store, nanoflann::KDTreeSingleIndexAdaptorParams(10));
}

void CLandmarkDatabase::addToStore(int64_t id, const cv::Mat& descriptors)
{
	// The search codes are made from the descriptors as matched (so a
	// rebuild from stored uint8 codes gives what insertion gave).
	m_store.blocks.push_back(m_searchCodec.encode(descriptors));
	const cv::Mat& block = m_store.blocks.back();
	for (int r = 0; r < block.rows; r++)
	{
		m_store.rows.push_back(block.ptr(r));
		m_store.owner.push_back(id);
	}
}

void CLandmarkDatabase::insert(VisualLandmarkModel lm)
{
	if (lm.descriptors.cols != 128 || lm.descriptors.rows != static_cast<int>(lm.points.size()))
		throw std::invalid_argument("landmark descriptors must be one SIFT row (128 values) per point");
	if (m_landmarks.count(lm.id)) throw std::invalid_argument("landmark ID " + std::to_string(lm.id) + " exists");
	lm.descriptors = m_codec.encode(lm.descriptors);
	const int64_t id = lm.id;
	const auto& stored = m_landmarks.emplace(id, std::move(lm)).first->second;
	if (stored.descriptors.rows == 0) return;
	const size_t first = m_store.rows.size();
	addToStore(id, DescriptorCodec::decode(stored.descriptors));
	m_index->addPoints(static_cast<uint32_t>(first), static_cast<uint32_t>(m_store.rows.size() - 1));
}

void CLandmarkDatabase::remove(int64_t id)
{
	const auto it = m_landmarks.find(id);
	if (it == m_landmarks.end()) return;
	// The index keeps reading removed rows until it is rebuilt, so the
	// landmark's data lives on until then.
	for (size_t i = 0; i < m_store.owner.size(); i++)
		if (m_store.owner[i] == id)
		{
			m_index->removePoint(i);
			m_removedRows++;
		}
	m_landmarks.erase(it);
	if (m_removedRows * 2 > m_store.rows.size()) rebuildIndex();
}

VisualLandmarkModel* CLandmarkDatabase::find(int64_t id)
{
	const auto it = m_landmarks.find(id);
	return it == m_landmarks.end() ? nullptr : &it->second;
}

const VisualLandmarkModel* CLandmarkDatabase::find(int64_t id) const
{
	const auto it = m_landmarks.find(id);
	return it == m_landmarks.end() ? nullptr : &it->second;
}

std::vector<CLandmarkDatabase::Candidate> CLandmarkDatabase::candidates(const ImageFeatures& image) const
{
	std::vector<Candidate> out;
	if (m_landmarks.empty() || image.searchCodes.rows == 0) return out;
	std::map<int64_t, int> votes;
	const float ratio2 = static_cast<float>(m_options.match_ratio * m_options.match_ratio);
	const nanoflann::SearchParams params(32, static_cast<float>(m_options.search_eps));
	const cv::Mat& query = image.searchCodes;
	for (int q = 0; q < query.rows; q++)
	{
		uint32_t idx[2];
		float dist[2];
		nanoflann::KNNResultSet<float, uint32_t> result(2);
		result.init(idx, dist);
		m_index->findNeighbors(result, query.ptr<float>(q), params);
		if (result.size() < 1) continue;
		// Second neighbour from another landmark is the meaningful rival.
		if (result.size() == 2 && m_store.owner[idx[0]] != m_store.owner[idx[1]] && !(dist[0] < ratio2 * dist[1]))
			continue;
		votes[m_store.owner[idx[0]]]++;
	}
	for (const auto& [id, n] : votes)
		if (n >= m_options.recognition_min_votes) out.push_back({id, n});
	std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) { return a.votes > b.votes; });
	if (static_cast<int>(out.size()) > m_options.recognition_max_candidates) out.resize(m_options.recognition_max_candidates);
	return out;
}

size_t CLandmarkDatabase::landmarkBytes() const
{
	size_t b = 0;
	for (const auto& [id, lm] : m_landmarks) b += lm.bytes();
	return b;
}

size_t CLandmarkDatabase::indexBytes() const
{
	size_t b = m_store.rows.capacity() * sizeof(void*) + m_store.owner.capacity() * sizeof(int64_t);
	for (const auto& block : m_store.blocks) b += block.total() * block.elemSize();
	for (const auto& sub : m_index->getAllIndices())
		b += sub.pool.usedMemory + sub.pool.wastedMemory + sub.vAcc.capacity() * sizeof(uint32_t);
	return b;
}
