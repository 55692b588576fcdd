#include <libvslam/frontend/DescriptorCodec.h>

#include <random>
#include <stdexcept>

using namespace vslam;

namespace
{
constexpr uint32_t kProjectionSeed = 20050418;  // fixed: same codes everywhere
}  // namespace

DescriptorCodec::DescriptorCodec(Kind kind, int dims) : m_kind(kind)
{
	if (kind != Kind::Projected) return;
	if (dims < 4 || dims > 128) throw std::invalid_argument("projected descriptor dimensions must be in [4, 128]");
	std::mt19937 rng(kProjectionSeed);
	std::normal_distribution<float> g;
	cv::Mat random(128, 128, CV_32F);
	for (int r = 0; r < 128; r++)
		for (int c = 0; c < 128; c++) random.at<float>(r, c) = g(rng);
	// Orthonormal rows: Gram-Schmidt on the first `dims` random rows.
	m_projection = cv::Mat(dims, 128, CV_32F);
	for (int r = 0; r < dims; r++)
	{
		cv::Mat v = random.row(r).clone();
		for (int k = 0; k < r; k++) v -= m_projection.row(k).dot(v) * m_projection.row(k);
		v /= cv::norm(v);
		v.copyTo(m_projection.row(r));
	}
}

cv::Mat DescriptorCodec::encode(const cv::Mat& d) const
{
	cv::Mat f;
	d.convertTo(f, CV_32F);
	cv::Mat out;
	switch (m_kind)
	{
		case Kind::Float:
			return f.clone();
		case Kind::Uint8:
			f.convertTo(out, CV_8U);  // rounds and saturates
			return out;
		case Kind::Projected:
		{
			if (f.rows == 0) return cv::Mat(0, m_projection.rows, CV_8S);
			const cv::Mat projected = f * m_projection.t();
			projected.convertTo(out, CV_8S, 1.0 / kProjectedStep);
			return out;
		}
	}
	return out;
}

cv::Mat DescriptorCodec::decode(const cv::Mat& codes)
{
	cv::Mat f;
	if (codes.type() == CV_8S)
		codes.convertTo(f, CV_32F, kProjectedStep);
	else
		codes.convertTo(f, CV_32F);
	return f;
}

size_t DescriptorCodec::bytesPerDescriptor() const
{
	switch (m_kind)
	{
		case Kind::Float:
			return 128 * sizeof(float);
		case Kind::Uint8:
			return 128;
		case Kind::Projected:
			return static_cast<size_t>(m_projection.rows);
	}
	return 0;
}

DescriptorCodec::Kind DescriptorCodec::parse(const std::string& n)
{
	if (n == "float") return Kind::Float;
	if (n == "uint8") return Kind::Uint8;
	if (n == "projected") return Kind::Projected;
	throw std::invalid_argument("descriptor storage '" + n + "' (use float, uint8 or projected)");
}

const char* DescriptorCodec::name(Kind k)
{
	return k == Kind::Float ? "float" : k == Kind::Uint8 ? "uint8" : "projected";
}
