#pragma once
/** \file DescriptorCodec.h
 * How landmark descriptors are stored (the paper's weak point: 40-500 kB
 * per landmark). SIFT descriptors are 128 values in 0..255:
 *  - float: as computed, 512 bytes each;
 *  - uint8: rounded to bytes, 128 bytes, nothing lost but rounding;
 *  - uint4: 4 bits per value on a square-root scale (fine steps for the
 *    many small values, coarse ones for the few large), two values per
 *    byte: 64 bytes;
 *  - projected: a fixed random orthonormal projection to `dims` values
 *    (Johnson-Lindenstrauss: distances are kept up to a small relative
 *    error), each rounded to a signed byte: `dims` bytes.
 * Matching and the k-d tree work on the decoded codes (floats), and image
 * descriptors go through the same encoding first, so both sides carry the
 * same rounding. The projection is drawn from a fixed seed: the same on
 * every run and machine, and independent of any data. A code's type and
 * width say how it was stored (float: CV_32F; uint8: CV_8U, 128 columns;
 * uint4: CV_8U, 64 columns; projected: CV_8S), so decode() needs no codec.
 */
#include <opencv2/core.hpp>

#include <string>

namespace vslam
{
class DescriptorCodec
{
   public:
	enum class Kind
	{
		Float,
		Uint8,
		Uint4,
		Projected
	};
	DescriptorCodec(Kind kind, int projectedDims);

	/** N x 128 CV_32F SIFT descriptors -> stored codes. */
	cv::Mat encode(const cv::Mat& descriptors) const;
	/** Stored codes -> N x dims() CV_32F, the space matching happens in. */
	static cv::Mat decode(const cv::Mat& codes);
	/** decode(encode(d)): image descriptors in the matching space. */
	cv::Mat toMatchingSpace(const cv::Mat& descriptors) const { return decode(encode(descriptors)); }
	/** What a descriptor index keeps of its rows: projected codes as the
	 * signed bytes they are (value = kProjectedStep x byte, a quarter of
	 * the floats), any other kind as toMatchingSpace() values (CV_32F). */
	cv::Mat indexRows(const cv::Mat& descriptors) const
	{
		return m_kind == Kind::Projected ? encode(descriptors) : toMatchingSpace(descriptors);
	}

	Kind kind() const { return m_kind; }
	int dims() const { return m_kind == Kind::Projected ? m_projection.rows : 128; }
	size_t bytesPerDescriptor() const;

	/** Value of one unit of a projected (signed byte) code. SIFT values
	 * reach ~160 and the projection keeps norms, so projected values stay
	 * within about +-250. */
	static constexpr float kProjectedStep = 2.0f;
	/** uint4: value v is stored as round(sqrt(v) / kUint4RootStep), at most
	 * 15; SIFT values above (15 * kUint4RootStep)^2 = 158.8 saturate. */
	static constexpr float kUint4RootStep = 0.84f;

	static Kind parse(const std::string& name);  //!< float | uint8 | uint4 | projected
	static const char* name(Kind kind);

   private:
	Kind m_kind;
	cv::Mat m_projection;  //!< dims x 128, CV_32F, orthonormal rows
};
}  // namespace vslam
