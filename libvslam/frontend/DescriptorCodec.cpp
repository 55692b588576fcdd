#include <libvslam/frontend/DescriptorCodec.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace vslam;

namespace
{
constexpr uint32_t kProjectionSeed = 20050418;  // fixed: same codes everywhere
constexpr int kSiftDims = 128;

uint8_t uint4Level(float v)
{
	const float level = std::round(std::sqrt(std::max(v, 0.0f)) / DescriptorCodec::kUint4RootStep);
	return static_cast<uint8_t>(std::min(level, 15.0f));
}

/** Two 4-bit levels per byte: value 2k in the low nibble, 2k+1 in the high. */
cv::Mat encodeUint4(const cv::Mat& f)
{
	cv::Mat out(f.rows, kSiftDims / 2, CV_8U);
	for (int r = 0; r < f.rows; r++)
	{
		const float* in = f.ptr<float>(r);
		uint8_t* code = out.ptr<uint8_t>(r);
		for (int k = 0; k < kSiftDims / 2; k++)
			code[k] = static_cast<uint8_t>(uint4Level(in[2 * k]) | (uint4Level(in[2 * k + 1]) << 4));
	}
	return out;
}

cv::Mat decodeUint4(const cv::Mat& codes)
{
	cv::Mat out(codes.rows, kSiftDims, CV_32F);
	for (int r = 0; r < codes.rows; r++)
	{
		const uint8_t* code = codes.ptr<uint8_t>(r);
		float* v = out.ptr<float>(r);
		for (int k = 0; k < kSiftDims / 2; k++)
		{
			const float lo = (code[k] & 0x0F) * DescriptorCodec::kUint4RootStep;
			const float hi = (code[k] >> 4) * DescriptorCodec::kUint4RootStep;
			v[2 * k] = lo * lo;
			v[2 * k + 1] = hi * hi;
		}
	}
	return out;
}
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
		case Kind::Uint4:
			if (f.cols != kSiftDims) throw std::invalid_argument("uint4 storage needs 128-value descriptors");
			return encodeUint4(f);
		case Kind::Projected:
		{
			if (f.rows == 0) return cv::Mat(0, m_projection.rows, CV_8S);
			if (f.cols != m_projection.cols) throw std::invalid_argument("projected storage needs 128-value descriptors");
			// Eigen, not cv::gemm: OpenCV hands the product to the system's
			// BLAS, which on Debian is the reference one, 10x slower here.
			const cv::Mat fc = f.isContinuous() ? f : f.clone();
			cv::Mat projected(f.rows, m_projection.rows, CV_32F);
			using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
			Eigen::Map<RowMajor>(projected.ptr<float>(), projected.rows, projected.cols).noalias() =
				Eigen::Map<const RowMajor>(fc.ptr<float>(), fc.rows, fc.cols) *
				Eigen::Map<const RowMajor>(m_projection.ptr<float>(), m_projection.rows, m_projection.cols).transpose();
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
	else if (codes.type() == CV_8U && codes.cols == kSiftDims / 2)
		return decodeUint4(codes);
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
		case Kind::Uint4:
			return 64;
		case Kind::Projected:
			return static_cast<size_t>(m_projection.rows);
	}
	return 0;
}

DescriptorCodec::Kind DescriptorCodec::parse(const std::string& n)
{
	if (n == "float") return Kind::Float;
	if (n == "uint8") return Kind::Uint8;
	if (n == "uint4") return Kind::Uint4;
	if (n == "projected") return Kind::Projected;
	throw std::invalid_argument("descriptor storage '" + n + "' (use float, uint8, uint4 or projected)");
}

const char* DescriptorCodec::name(Kind k)
{
	switch (k)
	{
		case Kind::Float:
			return "float";
		case Kind::Uint8:
			return "uint8";
		case Kind::Uint4:
			return "uint4";
		case Kind::Projected:
			return "projected";
	}
	return "?";
}
