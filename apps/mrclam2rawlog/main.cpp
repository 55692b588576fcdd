/** mrclam2rawlog: one robot of an MRCLAM data set to an MRPT rawlog
 * (see MrclamImporter.h for the conversion and the start-pose choice).
 *
 *   mrclam2rawlog DATASET_DIR ROBOT OUTPUT.rawlog [--odometry-delay S]
 *                 [--max-step-gap S] [--std-range M] [--std-bearing-deg D]
 *
 * Writes OUTPUT.rawlog, OUTPUT_groundtruth.tum and OUTPUT_landmarks.txt. */
#include <libvslam/app/ToolArguments.h>
#include <libvslam/app/ToolMain.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/MrclamImporter.h>
#include <libvslam/io/RawlogWriting.h>

#include <cstdlib>
#include <iostream>

namespace
{
const char* kUsage =
	"Usage: mrclam2rawlog DATASET_DIR ROBOT OUTPUT.rawlog [--odometry-delay S]\n"
	"                     [--max-step-gap S] [--std-range M] [--std-bearing-deg D]\n"
	"                     [--sigma-T S] [--sigma-R S] [--sigma-R-per-meter S]\n"
	"  --odometry-delay S   the robot moves S seconds after its odometry rows\n"
	"                       (default: estimated from the robot's own landmark\n"
	"                       sightings, no ground truth used)\n"
	"  --sigma-*            odometry noise model written into each action's\n"
	"                       covariance (defaults 0.08, 0.1, 0.1: robot 1's odometry)\n";
}  // namespace

int main(int argc, const char** argv)
{
	using namespace vslam;
	return vslam::runTool("mrclam2rawlog", kUsage, [&]() -> int {
		TMrclamImportOptions o;
		std::vector<std::string> positional;
		for (int i = 1; i < argc; i++)
		{
			const std::string a = argv[i];
			const auto next = [&] {
				if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
				return argv[++i];
			};
			if (a == "--help" || a == "-h")
			{
				std::cout << kUsage;
				return 0;
			}
			if (a == "--odometry-delay")
				o.odometry_delay = numberArgument(a, next());
			else if (a == "--max-step-gap")
				o.max_step_gap = numberArgument(a, next());
			else if (a == "--sigma-T")
				o.motion.sigma_T = numberArgument(a, next());
			else if (a == "--sigma-R")
				o.motion.sigma_R = numberArgument(a, next());
			else if (a == "--sigma-R-per-meter")
				o.motion.sigma_R_per_meter = numberArgument(a, next());
			else if (a == "--std-range")
				o.std_range = numberArgument(a, next());
			else if (a == "--std-bearing-deg")
				o.std_bearing = numberArgument(a, next()) * M_PI / 180;
			else if (a.rfind("--", 0) == 0)
				throw std::invalid_argument("unknown option '" + a + "'");
			else
				positional.push_back(a);
		}
		if (positional.size() != 3)
			throw std::invalid_argument("expected DATASET_DIR ROBOT OUTPUT.rawlog");
		o.robot = static_cast<int>(numberArgument("ROBOT", positional[1]));
		const MrclamImport im = importMrclam(positional[0], o);
		const std::string& rawlog = positional[2];
		writeActionFrameRawlog(rawlog, im.steps);
		writeTumTrajectory(siblingFile(rawlog, "_groundtruth.tum"), im.groundTruth);
		writeMrclamLandmarks(siblingFile(rawlog, "_landmarks.txt"), im.landmarks);
		std::cout << "mrclam2rawlog: robot " << o.robot << ": " << im.steps.size() << " steps, "
				  << im.measurementsUsed << " of " << im.measurementRows
				  << " measurements used (dropped: " << im.droppedFalseBarcodes
				  << " false barcodes, " << im.droppedRobotSightings << " other robots, "
				  << im.droppedOutsideOdometry << " outside the odometry span); start pose "
				  << "in the world frame: (" << im.startPoseWorld.x << ", " << im.startPoseWorld.y
				  << ", " << im.startPoseWorld.phi << " rad); odometry delay " << im.odometryDelay << " s ("
				  << (o.odometry_delay ? "given" : im.odometryDelayEstimated ? "estimated from the sightings"
																			: "too few sightings to tell")
				  << ") -> " << rawlog << "\n";
		return 0;
	});
}
