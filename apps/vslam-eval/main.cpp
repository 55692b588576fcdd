/** vslam-eval: absolute trajectory error of an estimate against ground
 * truth (Sturm et al. 2012 conventions, planar).
 *
 *   vslam-eval ESTIMATE GROUND_TRUTH [--align] [--max-gap SECONDS]
 *              [--plot FILE.png [--odometry PATH] [--world WORLD_FILE]]
 *
 * Both files may be TUM ("t x y z qx qy qz qw") or rbpf-slam's
 * log_estimated_path.txt ("step x y z yaw pitch roll t"). Estimated poses
 * are associated with the ground truth interpolated at their timestamps. */
#include <libvslam/core/InputError.h>
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/eval/TrajectoryPlot.h>
#include <libvslam/world/FloorPlanFile.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

namespace
{
const char* kUsage =
	"Usage: vslam-eval ESTIMATE GROUND_TRUTH [--align] [--max-gap SECONDS]\n"
	"                  [--plot FILE.png [--odometry PATH] [--world WORLD_FILE]]\n"
	"  ESTIMATE, GROUND_TRUTH: TUM (timestamp x y z qx qy qz qw), rbpf-slam's\n"
	"  log_estimated_path.txt (step x y z yaw pitch roll timestamp), or (ground truth)\n"
	"  an MRPT per-step pose list (x y z yaw pitch roll); detected per file. Ground\n"
	"  truth is interpolated at the estimate's timestamps (matched by step for pose lists).\n"
	"  --align: SE(2) alignment before the error. --max-gap: largest ground-truth\n"
	"  gap to interpolate across (s). --plot: the paths as a PNG (estimate, after the\n"
	"  alignment if --align; ground truth; odometry if given) over the floor plan of a\n"
	"  vslam-simul world file if given (textures under /usr/share).\n";
}

int main(int argc, const char** argv)
{
	using namespace vslam;
	try
	{
		AteOptions o;
		std::vector<std::string> files;
		std::string plotFile, odometryFile, worldFile;
		for (int i = 1; i < argc; i++)
		{
			const std::string a = argv[i];
			if (a == "--help" || a == "-h")
			{
				std::cout << kUsage;
				return 0;
			}
			if (a == "--align")
				o.align = true;
			else if (a == "--max-gap" && i + 1 < argc)
			{
				char* end = nullptr;
				o.maxGap = std::strtod(argv[++i], &end);
				if (*end != '\0' || !(o.maxGap > 0))
					throw std::invalid_argument("--max-gap needs a positive number");
			}
			else if ((a == "--plot" || a == "--odometry" || a == "--world") && i + 1 < argc)
				(a == "--plot" ? plotFile : a == "--odometry" ? odometryFile : worldFile) = argv[++i];
			else if (a.rfind("--", 0) == 0)
				throw std::invalid_argument("unknown option '" + a + "'");
			else
				files.push_back(a);
		}
		if (files.size() != 2) throw std::invalid_argument("expected ESTIMATE GROUND_TRUTH");
		const Trajectory estimate = readTrajectory(files[0]), truth = readTrajectory(files[1]);
		const AteStats s = computeAte(estimate, truth, o);
		if (s.associated == 0)
			throw InputError("no estimated pose has ground truth at its time");
		std::printf("ate%s: poses %zu rmse %.4f mean %.4f median %.4f max %.4f heading_rmse_deg %.3f\n",
			o.align ? "_se2_aligned" : "", s.associated, s.rmse, s.mean, s.median, s.max,
			s.headingRmse * 180 / M_PI);
		if (!plotFile.empty())
		{
			Trajectory aligned = estimate;
			for (auto& p : aligned) p.pose = se2::compose(s.alignment, p.pose);
			const Trajectory odometry = odometryFile.empty() ? Trajectory() : readTrajectory(odometryFile);
			std::vector<PlotSeries> series;
			if (!odometry.empty()) series.push_back({&odometry, {220, 0, 0}, "odometry", {}});
			series.push_back({&truth, {0, 160, 0}, "ground truth", {}});
			series.push_back({&aligned, {0, 60, 220}, o.align ? "estimate (aligned)" : "estimate", {}});
			std::optional<world::FloorPlan> plan;
			if (!worldFile.empty()) plan = world::loadFloorPlan(worldFile, "/usr/share");
			writeTrajectoryPlot(plan ? &*plan : nullptr, series, plotFile);
		}
		return 0;
	}
	catch (const std::invalid_argument& e)
	{
		std::cerr << "vslam-eval: error: " << e.what() << "\n" << kUsage;
		return 1;
	}
	catch (const std::exception& e)
	{
		std::cerr << "vslam-eval: error: " << e.what() << "\n";
		return 3;
	}
}
