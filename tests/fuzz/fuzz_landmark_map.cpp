/** Fuzz target: prior map files, as `[vslam] prior_map_file` reads them:
 * final_map.vslam (a serialized map) or text rows (final_map.txt, "id x y
 * [phi]"). Any outcome but a map or an InputError is a finding. */
#include <libvslam/app/RunMap.h>
#include <libvslam/core/InputError.h>
#include <tests/fuzz/FuzzInput.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const std::string file = vslam::fuzz::scratchPath("map");
	vslam::fuzz::writeBytes(file, data, size);
	try
	{
		const vslam::CVSlamMap map = vslam::readPriorMap(file, 0.05, 0.03);
		vslam::estimatesOf(map);
	}
	catch (const vslam::InputError&)
	{
	}
	return 0;
}
