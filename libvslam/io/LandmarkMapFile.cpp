#include <libvslam/core/InputError.h>
#include <libvslam/io/LandmarkMapFile.h>

#include <cstdio>

namespace vslam
{
void writeLandmarkMap(
	const std::string& file, const CLandmarkIndex& index, const LandmarkBank& bank)
{
	FILE* f = std::fopen(file.c_str(), "wt");
	if (!f) throw InputError("cannot create output file '" + file + "'");
	std::fprintf(f,
		"%% id kind x y phi var_x cov_xy cov_xphi var_y cov_yphi var_phi measurements\n");
	for (size_t slot = 0; slot < bank.size(); slot++)
	{
		const auto& e = index.entry(slot);
		const auto& l = bank[slot];
		const auto& C = l.cov;
		std::fprintf(f, "%lld %s %.6f %.6f %.6f %.9g %.9g %.9g %.9g %.9g %.9g %llu\n",
			static_cast<long long>(e.key.id), toString(e.key.kind), l.mean[0], l.mean[1],
			l.mean[2], C(0, 0), C(0, 1), C(0, 2), C(1, 1), C(1, 2), C(2, 2),
			static_cast<unsigned long long>(e.measurements));
	}
	std::fclose(f);
}
}  // namespace vslam
