#pragma once
/** \file KdTreeDescriptorIndex.h
 * DescriptorIndex on nanoflann's incremental k-d tree index (a forest of
 * power-of-two sub-trees, each rebuilt as rows arrive), searched with
 * nanoflann's eps-approximate k-NN. The codes are kept as the codec stores
 * them (signed bytes when projected). Its cost per query grows with the
 * map: in 16 dimensions the trees prune little.
 */
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/DescriptorIndex.h>
#include <nanoflann.hpp>

namespace vslam
{
class KdTreeDescriptorIndex : public DescriptorIndex
{
   public:
	KdTreeDescriptorIndex(const DescriptorCodec& codec, double eps);
	~KdTreeDescriptorIndex() override;

   protected:
	void doAdd(size_t firstRow, const cv::Mat& indexRows) override;
	void doSearch(const cv::Mat& queries, std::vector<TwoNearestLiveRows>& out) const override;
	size_t doBytes() const override;

   private:
	/** nanoflann's view of the codes, one block per landmark; row i at rows[i]. */
	struct Store
	{
		std::vector<const void*> rows;
		std::vector<cv::Mat> blocks;
		bool bytes = true;  //!< signed bytes of the projection, or floats
		size_t kdtree_get_point_count() const { return rows.size(); }
		float kdtree_get_pt(size_t i, size_t d) const
		{
			return bytes ? DescriptorCodec::kProjectedStep * static_cast<const int8_t*>(rows[i])[d]
						 : static_cast<const float*>(rows[i])[d];
		}
		template <class BBox>
		bool kdtree_get_bbox(BBox&) const
		{
			return false;
		}
	};
	using Tree =
		nanoflann::KDTreeSingleIndexDynamicAdaptor<nanoflann::L2_Simple_Adaptor<float, Store>, Store, -1, uint32_t>;

	double m_eps;
	Store m_store;
	std::unique_ptr<Tree> m_tree;  // reads m_store
};
}  // namespace vslam
