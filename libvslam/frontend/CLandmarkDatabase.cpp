#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/CLandmarkDatabase.h>

#include <algorithm>
#include <stdexcept>

using namespace vslam;

void CLandmarkDatabase::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace config;
	search.index = readWord(c, s, "search_index", search.index, {"flann", "bbf"});
	search.checks = readCount(c, s, "search_checks", search.checks, 1, 100000);
	search.bbf_compared = readCount(c, s, "search_bbf_compared", search.bbf_compared, 1, 100000000);
	search_dims = readCount(c, s, "search_dims", search_dims, 4, 128);
	descriptor_storage = readWord(c, s, "descriptor_storage", descriptor_storage, {"float", "uint8", "uint4", "projected"});
	descriptor_dims = readCount(c, s, "descriptor_dims", descriptor_dims, 4, 128);
	min_votes = readCount(c, s, "min_votes", min_votes, 1, 100000);
	max_candidates = readCount(c, s, "max_candidates", max_candidates, 1, 1000);
	max_landmarks = readCount(c, s, "max_landmarks", max_landmarks, 0, 1e9);
	prune_after_misses = readCount(c, s, "prune_after_misses", prune_after_misses, 0, 1e9);
}

void CLandmarkDatabase::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "search_index", search.index, 30, 10, "Descriptor index: flann (bounded checks) | bbf (bounded codes compared)");
	c.write(s, "search_checks", search.checks, 30, 10, "flann: leaves checked per query and level");
	c.write(s, "search_bbf_compared", search.bbf_compared, 30, 10, "bbf: codes compared per query and level (leaves of 8)");
	c.write(s, "search_dims", search_dims, 30, 10, "Dimensions of the projection the k-d tree votes in (128: none)");
	c.write(s, "descriptor_storage", descriptor_storage, 30, 10, "float | uint8 (128 B) | uint4 (64 B) | projected (descriptor_dims B)");
	c.write(s, "descriptor_dims", descriptor_dims, 30, 10, "Dimensions kept by the projected storage");
	c.write(s, "min_votes", min_votes, 30, 10, "Feature votes that make a landmark a candidate for recognition");
	c.write(s, "max_candidates", max_candidates, 30, 10, "Candidates tried per image");
	c.write(s, "max_landmarks", max_landmarks, 30, 10, "Landmarks kept at most (0: no limit)");
	c.write(s, "prune_after_misses", prune_after_misses, 30, 10, "Remove a landmark missed this often in a row when expected (0: never)");
}

CLandmarkDatabase::CLandmarkDatabase(const TOptions& options, double matchRatio)
	: m_options(options),
	  m_matchRatio(matchRatio),
	  m_codec(DescriptorCodec::parse(options.descriptor_storage), options.descriptor_dims),
	  m_searchCodec(options.search_dims < 128 ? DescriptorCodec::Kind::Projected : DescriptorCodec::Kind::Float,
		  options.search_dims)
{
	rebuildIndex();
}

CLandmarkDatabase::~CLandmarkDatabase() = default;

void CLandmarkDatabase::rebuildIndex()
{
	m_index = DescriptorIndex::create(m_options.search, m_searchCodec);
	// The search codes are made from the descriptors as matched (so a
	// rebuild from stored uint8 codes gives what insertion gave).
	std::vector<std::pair<int64_t, cv::Mat>> owned;
	for (const auto& [id, lm] : m_landmarks) owned.emplace_back(id, lm.descriptors);
	m_index->addStored(owned);
}

void CLandmarkDatabase::insert(VisualLandmarkModel lm)
{
	if (lm.descriptors.cols != 128 || lm.descriptors.rows != static_cast<int>(lm.points.size()))
		throw std::invalid_argument("landmark descriptors must be one SIFT row (128 values) per point");
	if (m_landmarks.count(lm.id)) throw std::invalid_argument("landmark ID " + std::to_string(lm.id) + " exists");
	lm.descriptors = m_codec.encode(lm.descriptors);
	const int64_t id = lm.id;
	const auto& stored = m_landmarks.emplace(id, std::move(lm)).first->second;
	m_index->add(id, DescriptorCodec::decode(stored.descriptors));
}

void CLandmarkDatabase::insertStored(std::vector<VisualLandmarkModel> landmarks)
{
	const cv::Mat storedForm = m_codec.encode(cv::Mat::zeros(1, 128, CV_32F));
	// Every landmark is checked and converted before any goes in.
	for (auto& lm : landmarks)
	{
		if (m_landmarks.count(lm.id)) throw std::invalid_argument("landmark ID " + std::to_string(lm.id) + " exists");
		if (lm.descriptors.rows != static_cast<int>(lm.points.size()))
			throw std::invalid_argument("landmark " + std::to_string(lm.id) + ": one descriptor per point expected");
		if (lm.descriptors.type() == storedForm.type() && lm.descriptors.cols == storedForm.cols) continue;
		const cv::Mat values = DescriptorCodec::decode(lm.descriptors);
		if (lm.descriptors.type() == CV_8S || values.cols != 128)
			throw std::invalid_argument("landmark " + std::to_string(lm.id) + ": its descriptors are stored projected to " +
				std::to_string(lm.descriptors.cols) + " dimensions, which cannot be converted to descriptor_storage = " +
				m_options.descriptor_storage + " (dimensions " + std::to_string(storedForm.cols) + ")");
		lm.descriptors = m_codec.encode(values);
	}
	std::vector<std::pair<int64_t, cv::Mat>> owned;
	for (auto& lm : landmarks)
	{
		const int64_t id = lm.id;
		if (!m_landmarks.emplace(id, std::move(lm)).second)
			throw std::invalid_argument("landmark ID " + std::to_string(id) + " appears twice");
		owned.emplace_back(id, m_landmarks.at(id).descriptors);
	}
	m_index->addStored(owned);
}

void CLandmarkDatabase::remove(int64_t id)
{
	const auto it = m_landmarks.find(id);
	if (it == m_landmarks.end()) return;
	m_landmarks.erase(it);
	m_index->remove(id);
	if (m_index->removedRows() * 2 > m_index->rows()) rebuildIndex();
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
	const float ratio2 = static_cast<float>(m_matchRatio * m_matchRatio);
	for (const NearestLandmarkRows& nearest : m_index->twoNearest(image.searchCodes))
	{
		if (nearest.count < 1) continue;
		// Second neighbour from another landmark is the meaningful rival.
		if (nearest.count == 2 && nearest.owner[0] != nearest.owner[1] && !(nearest.dist[0] < ratio2 * nearest.dist[1]))
			continue;
		votes[nearest.owner[0]]++;
	}
	for (const auto& [id, n] : votes)
		if (n >= m_options.min_votes) out.push_back({id, n});
	std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) { return a.votes > b.votes; });
	if (static_cast<int>(out.size()) > m_options.max_candidates) out.resize(m_options.max_candidates);
	return out;
}

size_t CLandmarkDatabase::landmarkBytes() const
{
	size_t b = 0;
	for (const auto& [id, lm] : m_landmarks) b += lm.bytes();
	return b;
}

size_t CLandmarkDatabase::indexBytes() const { return m_index->bytes(); }
