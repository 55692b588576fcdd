#include <libvslam/core/InputError.h>
#include <libvslam/io/StrechaDataset.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <filesystem>

namespace fs = std::filesystem;
using namespace vslam;

std::vector<StrechaView> vslam::readStrechaDataset(const std::string& folder)
{
	const fs::path images = fs::path(folder) / "images", cameras = fs::path(folder) / "cameras";
	std::error_code ec;
	if (!fs::is_directory(images, ec) || !fs::is_directory(cameras, ec))
		throw InputError("'" + folder + "': expected folders images/ and cameras/");
	std::vector<StrechaView> views;
	for (const auto& entry : fs::directory_iterator(cameras))
	{
		const std::string file = entry.path().string();
		if (entry.path().extension() != ".camera") continue;
		StrechaView v;
		v.name = entry.path().stem().string();  // "0000.jpg"
		v.imageFile = (images / v.name).string();
		if (!fs::is_regular_file(v.imageFile, ec))
			throw InputError("'" + file + "': its image '" + v.imageFile + "' is missing");
		// 26 numbers: K (9), distortion (3), R (9), C (3), width height.
		std::ifstream in(file);
		std::vector<double> n;
		std::string token;
		while (in >> token)
		{
			char* end = nullptr;
			const double d = std::strtod(token.c_str(), &end);
			if (*end != '\0' || !std::isfinite(d))
				throw InputError("'" + file + "': '" + token + "' is not a finite number");
			n.push_back(d);
		}
		if (n.size() != 26)
			throw InputError("'" + file + "': expected 26 numbers (K, distortion, R, C, width height), found " +
				std::to_string(n.size()));
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
			{
				v.K(r, c) = n[3 * r + c];
				v.R(r, c) = n[12 + 3 * r + c];
			}
		v.distortion = {n[9], n[10], n[11]};
		v.C = {n[21], n[22], n[23]};
		if (!(n[24] > 0 && n[24] < 1e5 && n[25] > 0 && n[25] < 1e5))
			throw InputError("'" + file + "': image size must be positive");
		v.width = static_cast<int>(n[24]);
		v.height = static_cast<int>(n[25]);
		if (!(v.K(0, 0) > 0 && v.K(1, 1) > 0 && v.K.allFinite()))
			throw InputError("'" + file + "': focal lengths must be positive");
		if (!(v.R * v.R.transpose()).isIdentity(1e-4))
			throw InputError("'" + file + "': R is not a rotation matrix");
		views.push_back(std::move(v));
	}
	if (views.empty()) throw InputError("'" + cameras.string() + "': no .camera files");
	std::sort(views.begin(), views.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
	return views;
}
