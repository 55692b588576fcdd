/** vslam-frontend: the visual front-end alone. Reads a rawlog with camera
 * images (CObservationImage, either rawlog format), runs the front-end
 * with the odometry of the same rawlog, and writes an actions/sensory-frames
 * rawlog in which every image is replaced by the landmark observations made
 * of it (CObservationVisualLandmark, CObservationLandmarkCreated); other
 * observations are kept. The output can be inspected with rawlog-edit
 * (LD_PRELOAD=libvslam_obs.so) and fed to vslam, so the front-end and the
 * filter can be tested and timed separately.
 *
 *   vslam-frontend IN.rawlog OUT.rawlog [--config INI] [--set SECTION.KEY=VALUE ...]
 *                  [--ground-truth TRUE_PATH [--accuracy-csv FILE] [--heading-csv FILE]
 *                   [--oracle-rawlog FILE [--oracle-kind K]]]
 *
 * With --ground-truth (TUM or rbpf-slam path of the robot, e.g. from
 * vslam-simul), it also prints how right the measurements are: errors of
 * all measurements and of those the pre-filter ([vslam_prefilter] of the
 * INI and --set) accepts, and the share of accepted ones beyond 3 sigma of
 * [vslam_visual]'s Sigma_vis; --accuracy-csv writes every measurement
 * with its truth. --oracle-rawlog writes a second rawlog, the same but with
 * every landmark measurement replaced by its truth (same landmarks, same
 * recognitions, same statistics; measurements without truth dropped): fed
 * to vslam, it shows what the filter makes of a front-end with no
 * measurement error, which separates the front-end's share of a run's
 * error from the filter's. --oracle-kind splits that share: `all` (the
 * default) replaces every measurement, `outliers` only those beyond 3 sigma
 * of Sigma_vis, `inliers` only those within, `drop-outliers` keeps the
 * measured values but removes those beyond 3 sigma, and `scale` keeps them
 * too but takes each landmark's scale error out of its measurements (fitted
 * against the truth; --oracle-scale-bias B leaves the odometry's own scale
 * error B in, which no estimate from the odometry can see). With
 * [vslam_heading_measurement] enabled, it also prints the heading changes'
 * errors, their calibration (error over predicted std) and the odometry's
 * error over the same intervals; --heading-csv writes every heading change
 * with its truth.
 */
#include <libvslam/app/CVSlamApp.h>
#include <libvslam/app/ToolArguments.h>
#include <libvslam/app/ToolMain.h>
#include <libvslam/config/ConfigError.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/core/ActionOdometry.h>
#include <libvslam/core/InputError.h>
#include <libvslam/eval/HeadingChangeAccuracy.h>
#include <libvslam/eval/LandmarkScaleOracle.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/frontend/ImageBufferAllocation.h>
#include <libvslam/frontend/ImagesToMeasurements.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/obs/CObservationHeadingChange.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <libvslam/tools/MeasurementAccuracy.h>
#include <mrpt/obs/CObservationImage.h>
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/obs/registerClasses.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <iostream>
#include <optional>

namespace
{
vslam::CVSlamParticleFilter::TOptions loadFilterOptions(
	const std::string& iniFile, const std::vector<vslam::config::Override>& overrides)
{
	using namespace vslam;
	CVSlamParticleFilter::TOptions filter;
	try
	{
		const auto cfg =
			config::parseIniWithOverrides(iniFile.empty() ? std::string() : config::readIniFile(iniFile), overrides);
		config::checkNoUnknownKeys(cfg, CVSlamApp::knownKeys());
		filter.loadFromConfig(cfg);
	}
	catch (const ConfigError& e)
	{
		throw ConfigError((iniFile.empty() ? std::string("--set") : "'" + iniFile + "'") + ": " + e.what());
	}
	return filter;
}

void printAccuracy(const std::vector<vslam::LandmarkMeasurementRecord>& records,
	const std::map<int64_t, double>& creationTimes, const std::string& groundTruthFile,
	const vslam::CVSlamParticleFilter::TOptions& filter, const std::string& csvFile)
{
	using namespace vslam;
	const auto a = evaluateMeasurements(
		records, creationTimes, readTrajectory(groundTruthFile), filter.visual, filter.prefilter);
	const auto row = [](const char* name, const MeasurementErrorStats& s) {
		std::printf("vslam-frontend: %-9s %6zu  %10.3f m  %10.2f deg  %8.3f m  %8.2f deg  %5zu (%.2f%%)\n", name,
			s.count, s.medianPosition, s.medianHeadingDeg, s.rmsPosition, s.rmsHeadingDeg, s.beyond3Sigma,
			100 * s.shareBeyond3Sigma());
	};
	std::printf("vslam-frontend: accuracy against '%s' (%zu measurements, %zu without truth)\n",
		groundTruthFile.c_str(), a.measurements, a.withoutTruth);
	std::printf("vslam-frontend: %-9s %6s  %12s  %14s  %10s  %12s  %s\n", "", "count", "median pos", "median head",
		"rms pos", "rms head", "beyond 3 sigma");
	row("all", a.all);
	row("accepted", a.accepted);
	if (filter.visual.predicted_cov_scale > 0)
		std::printf("vslam-frontend: beyond 3 sigma of the noise the filter gives each measurement (Sigma_vis + %g^2 x "
					"its predicted covariance): all %zu (%.2f%%), accepted %zu (%.2f%%)\n",
			filter.visual.predicted_cov_scale, a.all.beyond3SigmaOfItsNoise, 100 * a.all.shareBeyond3SigmaOfItsNoise(),
			a.accepted.beyond3SigmaOfItsNoise, 100 * a.accepted.shareBeyond3SigmaOfItsNoise());
	std::printf("vslam-frontend: median e^T D^-1 e of the accepted, the squared error over the noise (2.37 if the "
				"noise were right): of Sigma_vis %.2f",
		a.accepted.medianNeesSigmaVis);
	if (filter.visual.predicted_cov_scale > 0) std::printf(", of the noise the filter gives each %.2f", a.accepted.medianNeesItsNoise);
	std::printf("\n");
	if (csvFile.empty()) return;
	FILE* f = std::fopen(csvFile.c_str(), "wt");
	if (!f) throw InputError("cannot create '" + csvFile + "'");
	std::fprintf(f, "t,landmark,dx,dy,dphi_deg,true_dx,true_dy,true_dphi_deg,ProjErrRMS,NPoints,Slope,accepted,"
		"beyond_3_sigma,pred_std_dx,pred_std_dy,pred_std_dphi_deg,Height,beyond_3_sigma_of_its_noise,Slope_std\n");
	for (const auto& e : a.errors)
		std::fprintf(f, "%.6f,%lld,%.5f,%.5f,%.4f,%.5f,%.5f,%.4f,%.4f,%u,%.5f,%d,%d,%.5f,%.5f,%.4f,%.5f,%d,%.6g\n", e.measurement.t,
			static_cast<long long>(e.measurement.landmarkID), e.measurement.z.x, e.measurement.z.y,
			e.measurement.z.phi * 180 / M_PI, e.expected.x, e.expected.y, e.expected.phi * 180 / M_PI,
			e.measurement.ProjErrRMS, e.measurement.NPoints, e.measurement.Slope, e.accepted ? 1 : 0,
			e.beyond3Sigma ? 1 : 0, e.measurement.predictedStdX, e.measurement.predictedStdY,
			e.measurement.predictedStdPhi * 180 / M_PI, e.measurement.Height, e.beyond3SigmaOfItsNoise ? 1 : 0,
			e.measurement.SlopeStd);
	std::fclose(f);
}

void printHeadingChangeAccuracy(const std::vector<vslam::HeadingChangeRecord>& records,
	const std::string& groundTruthFile, const std::string& csvFile)
{
	const auto a = vslam::evaluateHeadingChanges(records, vslam::readTrajectory(groundTruthFile));
	std::printf("vslam-frontend: heading changes: %zu against the truth (%zu without); error median %.4f deg, RMS "
				"%.4f deg, sum %.2f deg; predicted std median %.4f deg, error / predicted std RMS %.2f, median |.| "
				"%.2f (0.67 if right), beyond 3 predicted std %zu (%.2f%%); odometry over the same intervals: "
				"median %.4f deg, RMS %.4f deg, sum %.2f deg\n",
		a.count, a.withoutTruth, a.medianAbsErrorDeg, a.rmsErrorDeg, a.sumErrorDeg, a.medianPredictedStdDeg,
		a.rmsNormalizedError, a.medianAbsNormalizedError, a.beyond3Sigma,
		a.count ? 100.0 * static_cast<double>(a.beyond3Sigma) / static_cast<double>(a.count) : 0.0,
		a.odometryMedianAbsErrorDeg, a.odometryRmsErrorDeg, a.odometrySumErrorDeg);
	if (csvFile.empty()) return;
	FILE* f = std::fopen(csvFile.c_str(), "wt");
	if (!f) throw vslam::InputError("cannot create '" + csvFile + "'");
	std::fprintf(f, "t0,t1,dphi_deg,true_dphi_deg,pred_std_deg,odometry_dphi_deg,inliers,matches,rms_px\n");
	for (const auto& e : a.errors)
		std::fprintf(f, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%d,%d,%.4f\n", e.record.t0, e.record.t1,
			e.record.dphi * 180 / M_PI, e.trueDphi * 180 / M_PI, e.record.stdDphi * 180 / M_PI,
			e.record.odometryDphi * 180 / M_PI, e.record.inliers, e.record.matches, e.record.rmsPx);
	std::fclose(f);
}

enum class OracleKind
{
	All,
	Outliers,
	Inliers,
	DropOutliers,
	Scale
};

OracleKind parseOracleKind(const std::string& s)
{
	if (s == "all") return OracleKind::All;
	if (s == "outliers") return OracleKind::Outliers;
	if (s == "inliers") return OracleKind::Inliers;
	if (s == "drop-outliers") return OracleKind::DropOutliers;
	if (s == "scale") return OracleKind::Scale;
	throw std::invalid_argument("--oracle-kind '" + s + "': expected all, outliers, inliers, drop-outliers or scale");
}

/** Every landmark measurement in `steps` with its truth and whether it is
 * beyond 3 sigma of `sigma` from it: f(measurement, truth, outlier) returns
 * whether to keep it. Those without truth are dropped. */
template <typename F>
void forEachMeasurementWithTruth(std::vector<vslam::ActionFramePair>& steps, const vslam::Trajectory& truth,
	const vslam::CMeasurementExtractor::TVisualOptions& sigma, F&& f)
{
	using namespace vslam;
	std::map<int64_t, double> createdAt;
	for (auto& [action, sf] : steps)
	{
		std::vector<mrpt::obs::CObservation::Ptr> kept;
		for (const auto& o : *sf)
		{
			if (const auto* c = dynamic_cast<const CObservationLandmarkCreated*>(o.get()))
				createdAt[c->landmarkID] = mrpt::Clock::toDouble(c->timestamp);
			if (auto* m = dynamic_cast<CObservationVisualLandmark*>(o.get()))
			{
				const auto created = createdAt.find(m->landmarkID);
				const auto z = created == createdAt.end()
					? std::nullopt
					: trueLandmarkMeasurement(truth, mrpt::Clock::toDouble(m->timestamp), created->second);
				if (!z) continue;
				const bool outlier =
					beyondThreeSigma({m->relPose.x(), m->relPose.y(), m->relPose.phi()}, *z, sigma);
				if (!f(*m, *z, outlier)) continue;
			}
			kept.push_back(o);
		}
		sf->clear();
		for (auto& o : kept) sf->insert(o);
	}
}

vslam::se2::Pose planarMount(const vslam::CObservationVisualLandmark& m)
{
	return {m.sensorPoseOnRobot.x(), m.sensorPoseOnRobot.y(), m.sensorPoseOnRobot.yaw()};
}

/** Replaces the landmark measurements in `steps` that `kind` names by their
 * truth (the landmark frame's true pose seen from the robot's true pose),
 * or drops them (drop-outliers), or (scale) takes each landmark's scale
 * error out of all its measurements: the scale fitted over those within 3
 * sigma against the truth (LandmarkScaleOracle.h), over 1 + `scaleBias`
 * (the odometry's own scale error, which no estimate from it can see, is
 * left in). Those without truth are dropped. Outliers: beyond 3 sigma of
 * `sigma` from the truth. */
void replaceMeasurementsWithTruth(std::vector<vslam::ActionFramePair>& steps, const std::string& groundTruthFile,
	OracleKind kind, const vslam::CMeasurementExtractor::TVisualOptions& sigma, double scaleBias)
{
	using namespace vslam;
	const Trajectory truth = readTrajectory(groundTruthFile);
	std::map<int64_t, double> scaleOf;
	if (kind == OracleKind::Scale)
	{
		std::map<int64_t, std::vector<std::pair<se2::Pose, se2::Pose>>> inliersOf;
		std::map<int64_t, se2::Pose> mountOf;
		forEachMeasurementWithTruth(steps, truth, sigma,
			[&](const CObservationVisualLandmark& m, const se2::Pose& z, bool outlier) {
				if (!outlier)
					inliersOf[m.landmarkID].emplace_back(
						se2::Pose{m.relPose.x(), m.relPose.y(), m.relPose.phi()}, z);
				mountOf[m.landmarkID] = planarMount(m);
				return true;
			});
		for (const auto& [id, pairs] : inliersOf)
		{
			const double k = fitLandmarkScale(pairs, mountOf[id]);
			if (k > 0) scaleOf[id] = k / (1 + scaleBias);  // else no scale: left as measured
		}
	}
	forEachMeasurementWithTruth(steps, truth, sigma,
		[&](CObservationVisualLandmark& m, const se2::Pose& z, bool outlier) {
			if (kind == OracleKind::DropOutliers && outlier) return false;
			if (kind == OracleKind::Scale)
			{
				const auto k = scaleOf.find(m.landmarkID);
				if (k != scaleOf.end())
				{
					const se2::Pose r = withoutScale(
						{m.relPose.x(), m.relPose.y(), m.relPose.phi()}, planarMount(m), k->second);
					m.relPose = mrpt::poses::CPose2D(r.x, r.y, r.phi);
				}
				return true;
			}
			const bool replace = kind == OracleKind::All || (kind == OracleKind::Outliers && outlier) ||
				(kind == OracleKind::Inliers && !outlier);
			if (replace) m.relPose = mrpt::poses::CPose2D(z.x, z.y, z.phi);
			return true;
		});
}

const char* kUsage =
	"Usage: vslam-frontend IN.rawlog OUT.rawlog [--config INI] [--set SECTION.KEY=VALUE ...]\n"
	"                      [--ground-truth TRUE_PATH [--accuracy-csv FILE] [--heading-csv FILE]\n"
	"                       [--oracle-rawlog FILE [--oracle-kind all|outliers|inliers|drop-outliers|scale]\n"
	"                        [--oracle-scale-bias B]]]\n"
	"       vslam-frontend --print-default-config\n";

/** The command line, checked. */
struct FrontEndCommand
{
	std::string in, out, iniFile, groundTruthFile, csvFile, oracleFile, headingCsvFile;
	std::vector<vslam::config::Override> overrides;
	OracleKind oracleKind = OracleKind::All;
	std::optional<double> oracleScaleBias;
};

FrontEndCommand parseCommand(const vslam::ToolArguments& args)
{
	FrontEndCommand c;
	if (args.positional.size() != 2) throw std::invalid_argument("expected IN.rawlog OUT.rawlog");
	c.in = args.positional[0];
	c.out = args.positional[1];
	c.overrides = args.overrides;
	c.iniFile = args.value("--config");
	c.groundTruthFile = args.value("--ground-truth");
	c.csvFile = args.value("--accuracy-csv");
	c.headingCsvFile = args.value("--heading-csv");
	c.oracleFile = args.value("--oracle-rawlog");
	if (args.values.count("--oracle-kind")) c.oracleKind = parseOracleKind(args.value("--oracle-kind"));
	if (args.values.count("--oracle-scale-bias"))
	{
		c.oracleScaleBias = vslam::numberArgument("--oracle-scale-bias", args.value("--oracle-scale-bias"));
		if (!(*c.oracleScaleBias > -1)) throw std::invalid_argument("--oracle-scale-bias must be above -1");
	}
	if ((!c.csvFile.empty() || !c.oracleFile.empty() || !c.headingCsvFile.empty()) && c.groundTruthFile.empty())
		throw std::invalid_argument("--accuracy-csv, --heading-csv and --oracle-rawlog need --ground-truth");
	if (c.oracleScaleBias && (c.oracleFile.empty() || c.oracleKind != OracleKind::Scale))
		throw std::invalid_argument("--oracle-scale-bias goes with --oracle-rawlog and --oracle-kind scale");
	return c;
}

/** The rawlog through the front-end: the output steps, and what the
 * accuracy figures need of the measurements it made. */
struct FrontEndPass
{
	std::vector<vslam::ActionFramePair> steps;
	vslam::ImagesToMeasurementsResult total;
	std::vector<vslam::LandmarkMeasurementRecord> records;
	std::vector<vslam::HeadingChangeRecord> headingRecords;
	std::map<int64_t, double> creationTimes;
	std::map<mrpt::Clock::time_point, double> odometryHeadingAtImage;

	/** Keeps what the front-end made of one sensory frame. */
	void record(const mrpt::obs::CSensoryFrame& sf)
	{
		using namespace vslam;
		for (const auto& o : sf)
		{
			if (const auto* m = dynamic_cast<const CObservationVisualLandmark*>(o.get()))
				records.push_back({mrpt::Clock::toDouble(m->timestamp), m->landmarkID,
					{m->relPose.x(), m->relPose.y(), m->relPose.phi()}, m->ProjErrRMS, m->NPoints, m->Slope, m->Height,
					std::sqrt(m->relPoseCov(0, 0)), std::sqrt(m->relPoseCov(1, 1)), std::sqrt(m->relPoseCov(2, 2)),
					m->SlopeStd});
			else if (const auto* c = dynamic_cast<const CObservationLandmarkCreated*>(o.get()))
				creationTimes[c->landmarkID] = mrpt::Clock::toDouble(c->timestamp);
			else if (const auto* h = dynamic_cast<const CObservationHeadingChange*>(o.get()))
			{
				const auto from = odometryHeadingAtImage.find(h->previousTimestamp);
				const auto to = odometryHeadingAtImage.find(h->timestamp);
				if (from != odometryHeadingAtImage.end() && to != odometryHeadingAtImage.end())
					headingRecords.push_back({mrpt::Clock::toDouble(h->previousTimestamp),
						mrpt::Clock::toDouble(h->timestamp), h->dphi, h->stdDphi, se2::wrap(to->second - from->second),
						static_cast<int>(h->NInliers), static_cast<int>(h->NMatches), h->rmsPx});
			}
		}
	}
};

FrontEndPass runFrontEnd(vslam::CVisualFrontEnd& frontEnd, const std::string& in)
{
	using namespace vslam;
	FrontEndPass pass;
	CRawlogReader reader(in);
	mrpt::poses::CPose2D odometry;
	RawlogStep step;
	while (reader.next(step))
	{
		if (step.action)
			if (const auto u = odometryIncrement(*step.action)) odometry = odometry + *u;
		for (const auto& o : *step.sf)
			if (dynamic_cast<const mrpt::obs::CObservationImage*>(o.get()))
				pass.odometryHeadingAtImage[o->timestamp] = odometry.phi();
		const auto r = replaceImagesWithMeasurements(
			frontEnd, *step.sf, odometry, "rawlog '" + in + "', entry " + std::to_string(step.entry));
		pass.total.images += r.images;
		pass.total.measurements += r.measurements;
		pass.total.created += r.created;
		pass.total.pruned += r.pruned;
		pass.total.headingChanges += r.headingChanges;
		pass.record(*step.sf);
		auto action = step.action ? step.action : mrpt::obs::CActionCollection::Create();
		pass.steps.emplace_back(action, step.sf);
	}
	return pass;
}

void printSummary(const vslam::CVisualFrontEnd& frontEnd, const vslam::ImagesToMeasurementsResult& total,
	double seconds, const std::string& out, bool headingChange)
{
	const auto& t = frontEnd.totalSeconds();
	const auto& db = frontEnd.database();
	const auto perImage = [&](double s) { return total.images ? 1000 * s / total.images : 0.0; };
	std::cout << "vslam-frontend: " << total.images << " images -> " << total.measurements << " landmark measurements, "
			  << total.created << " landmarks created, " << total.pruned << " pruned; " << db.size()
			  << " in the database (" << (db.size() ? db.landmarkBytes() / db.size() : 0) << " bytes each, index "
			  << db.indexBytes() << " bytes)\n"
			  << "vslam-frontend: ms per image: features " << perImage(t.features) << ", search " << perImage(t.search)
			  << ", pose " << perImage(t.pose) << ", creation " << perImage(t.creation) << ", heading change "
			  << perImage(t.heading) << "; total " << seconds << " s -> " << out << "\n";
	if (headingChange)
		std::cout << "vslam-frontend: heading changes: " << frontEnd.headingChangesMeasured() << " measured, "
				  << frontEnd.headingChangesFailed() << " image pairs without one\n";
	std::cout << "vslam-frontend: landmark creation: " << frontEnd.creationAttempts() << " attempts, " << total.created
			  << " built";
	for (const auto& [why, count] : frontEnd.creationRejections()) std::cout << "; " << count << " x " << why;
	std::cout << "\n";
	std::cout << "vslam-frontend: recognitions not reported: " << frontEnd.poorlyConditionedRecognitions()
			  << " degenerate, " << frontEnd.inconsistentRecognitions() << " inconsistent with the odometry ([vslam_recognition] odometry_gate_s)\n";
}
}  // namespace

int main(int argc, const char** argv)
{
	using namespace vslam;
	registerObservationClasses();
	keepImageBuffersInTheProcess();
	return vslam::runTool("vslam-frontend", kUsage, [&]() -> int {
		const ToolArguments args = parseToolArguments(argc, argv,
			{"--config", "--ground-truth", "--accuracy-csv", "--heading-csv", "--oracle-rawlog", "--oracle-kind",
				"--oracle-scale-bias"},
			{"--help", "--print-default-config"});
		if (args.has("--help"))
		{
			std::cout << kUsage;
			return 0;
		}
		if (args.has("--print-default-config"))
		{
			mrpt::config::CConfigFileMemory defaults;
			CVisualFrontEnd::TOptions().saveToConfig(defaults);
			std::string text;
			defaults.getContent(text);
			std::cout << text;
			return 0;
		}
		const FrontEndCommand c = parseCommand(args);
		const CVisualFrontEnd::TOptions options = loadFrontEndOptions(c.iniFile, c.overrides);
		// Sigma_vis and the pre-filter of the INI and the --set overrides, for
		// the accuracy figures; every vslam key checked before the long run.
		const CVSlamParticleFilter::TOptions filter = loadFilterOptions(c.iniFile, c.overrides);

		const auto start = std::chrono::steady_clock::now();
		CVisualFrontEnd frontEnd(options);
		FrontEndPass pass = runFrontEnd(frontEnd, c.in);
		writeActionFrameRawlog(c.out, pass.steps);
		const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
		printSummary(frontEnd, pass.total, seconds, c.out, options.heading.enabled);
		if (!c.groundTruthFile.empty()) printAccuracy(pass.records, pass.creationTimes, c.groundTruthFile, filter, c.csvFile);
		if (!c.groundTruthFile.empty() && options.heading.enabled)
			printHeadingChangeAccuracy(pass.headingRecords, c.groundTruthFile, c.headingCsvFile);
		if (!c.oracleFile.empty())
		{
			replaceMeasurementsWithTruth(pass.steps, c.groundTruthFile, c.oracleKind, filter.visual, c.oracleScaleBias.value_or(0));
			writeActionFrameRawlog(c.oracleFile, pass.steps);
			std::cout << "vslam-frontend: the same with "
					  << (c.oracleKind == OracleKind::Scale ? "the landmarks' scale errors taken out" : "true measurements")
					  << " -> " << c.oracleFile << "\n";
		}
		return 0;
	});
}
