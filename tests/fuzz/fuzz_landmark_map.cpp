/** Fuzz target: landmark map files (prior_map_file: final_map.txt rows or
 * "id x y [phi]" rows). Any outcome but a map or an InputError is a finding. */
#include <libvslam/core/InputError.h>
#include <libvslam/io/LandmarkMapFile.h>
#include <tests/fuzz/FuzzInput.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const std::string file = vslam::fuzz::scratchPath("map.txt");
	vslam::fuzz::writeBytes(file, data, size);
	try
	{
		vslam::readLandmarkMap(file, 0.05, 0.03);
	}
	catch (const vslam::InputError&)
	{
	}
	return 0;
}
