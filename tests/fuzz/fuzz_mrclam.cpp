/** Fuzz target: the MRCLAM importer's text parsing. Input: the five files of
 * one robot (Barcodes, Landmark_Groundtruth, Robot1_Odometry,
 * Robot1_Measurement, Robot1_Groundtruth), separated by lines "%%%%".
 * Any outcome but an import or an InputError is a finding. */
#include <libvslam/core/InputError.h>
#include <libvslam/io/MrclamImporter.h>
#include <tests/fuzz/FuzzInput.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const std::string dir = vslam::fuzz::scratchPath("mrclam");
	static const char* kFiles[] = {"Barcodes.dat", "Landmark_Groundtruth.dat",
		"Robot1_Odometry.dat", "Robot1_Measurement.dat", "Robot1_Groundtruth.dat"};
	std::filesystem::create_directories(dir);
	const auto parts = vslam::fuzz::splitAtLines(data, size, "%%%%");
	for (size_t i = 0; i < 5; i++)
	{
		const std::string path = dir + "/" + kFiles[i];
		if (i < parts.size())
			std::ofstream(path, std::ios::trunc) << parts[i];
		else
			std::filesystem::remove(path);
	}
	try
	{
		vslam::TMrclamImportOptions options;
		options.robot = 1;
		vslam::importMrclam(dir, options);
	}
	catch (const vslam::InputError&)
	{
	}
	return 0;
}
