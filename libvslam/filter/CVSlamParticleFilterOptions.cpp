#include <libvslam/config/StrictRead.h>
#include <libvslam/filter/CVSlamParticleFilter.h>

using namespace vslam;
using namespace vslam::config;
using mrpt::bayes::CParticleFilter;

namespace
{
const std::vector<std::string> kResamplingNames = {
	"prMultinomial", "prResidual", "prStratified", "prSystematic"};
}  // namespace

CParticleFilter::TParticleFilterOptions CVSlamParticleFilter::TParticleFilterOptions::toMrpt() const
{
	CParticleFilter::TParticleFilterOptions o;
	o.PF_algorithm = CParticleFilter::pfStandardProposal;
	o.adaptiveSampleSize = false;
	o.sampleSize = sampleSize;
	o.BETA = BETA;
	o.resamplingMethod = resamplingMethod;
	return o;
}

void CVSlamParticleFilter::TParticleFilterOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	sampleSize = static_cast<uint32_t>(
		readInt(c, s, "sampleSize", sampleSize, Range::closed(1, 1e5)));
	BETA = readDouble(c, s, "BETA", BETA, Range::closed(0, 1));
	resamplingMethod =
		static_cast<CParticleFilter::TParticleResamplingAlgorithm>(readChoice(
			c, s, "resamplingMethod", static_cast<size_t>(resamplingMethod),
			kResamplingNames));
	initialPose.x = readDouble(c, s, "initial_x", initialPose.x, Range::closed(-1e7, 1e7));
	initialPose.y = readDouble(c, s, "initial_y", initialPose.y, Range::closed(-1e7, 1e7));
	initialPose.phi = readDegreesAsRadians(c, s, "initial_phi_deg", initialPose.phi, Range::closed(-360, 360));
	initial_std_xy =
		readDouble(c, s, "initial_std_xy", initial_std_xy, Range::closed(0, 1000));
	initial_std_phi = readDegreesAsRadians(
		c, s, "initial_std_phi_deg", initial_std_phi, Range::closed(0, 360));
}

void CVSlamParticleFilter::TParticleFilterOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "sampleSize", static_cast<int>(sampleSize), 25, 12,
		"Number of particles");
	c.write(s, "BETA", BETA, 25, 12, "Resample when ESS < BETA, in [0,1]");
	c.write(s, "resamplingMethod", kResamplingNames.at(resamplingMethod), 25, 12,
		"prMultinomial | prResidual | prStratified | prSystematic");
	c.write(s, "initial_x", initialPose.x, 25, 12, "Initial robot pose x [m]");
	c.write(s, "initial_y", initialPose.y, 25, 12, "Initial robot pose y [m]");
	c.write(s, "initial_phi_deg", initialPose.phi * 180 / M_PI, 25, 12,
		"Initial robot heading [deg]");
	c.write(s, "initial_std_xy", initial_std_xy, 25, 12,
		"Initial spread of the particles [m] (0: all on the initial pose)");
	c.write(s, "initial_std_phi_deg", initial_std_phi * 180 / M_PI, 25, 12,
		"Initial heading spread [deg]");
}

void CVSlamParticleFilter::TLandmarkOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	init_std_xy = readDouble(c, s, "init_std_xy", init_std_xy, Range::closed(0, 100));
	init_std_phi = readDegreesAsRadians(
		c, s, "init_std_phi_deg", init_std_phi, Range::closed(0, 360));
	anchor_first_landmark = readBool(c, s, "anchor_first_landmark", anchor_first_landmark);
}

void CVSlamParticleFilter::TLandmarkOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "init_std_xy", init_std_xy, 25, 12,
		"Extra std of a new visual landmark's frame vs. the creating pose [m]");
	c.write(s, "init_std_phi_deg", init_std_phi * 180 / M_PI, 25, 12,
		"Extra heading std of a new visual landmark's frame [deg]");
	c.write(s, "anchor_first_landmark", anchor_first_landmark, 25, 12,
		"Collapse the particle cloud onto its mean when the first landmark is created (fixes the map frame)");
}

void CVSlamParticleFilter::TOptions::loadFromConfig(const mrpt::config::CConfigFileBase& c)
{
	pf.loadFromConfigFile(c, kParticleFilter);
	motion.loadFromConfigFile(c, kMotionModel);
	likelihood.loadFromConfigFile(c, kLikelihood);
	mixture.loadFromConfigFile(c, kMixture);
	kidnap.loadFromConfigFile(c, kKidnap);
	landmarks.loadFromConfigFile(c, kLandmarks);
	visual.loadFromConfigFile(c, kVisual);
	rangeBearing.loadFromConfigFile(c, kRangeBearing);
	headingChange.loadFromConfigFile(c, kHeadingChange);
	prefilter.loadFromConfigFile(c, kPreFilter);
	loopClosure.loadFromConfigFile(c, kLoopClosure);
	smoothedPose.loadFromConfigFile(c, kSmoothedPose);
}

void CVSlamParticleFilter::TOptions::saveToConfig(mrpt::config::CConfigFileBase& c) const
{
	pf.saveToConfigFile(c, kParticleFilter);
	motion.saveToConfigFile(c, kMotionModel);
	likelihood.saveToConfigFile(c, kLikelihood);
	mixture.saveToConfigFile(c, kMixture);
	kidnap.saveToConfigFile(c, kKidnap);
	landmarks.saveToConfigFile(c, kLandmarks);
	visual.saveToConfigFile(c, kVisual);
	rangeBearing.saveToConfigFile(c, kRangeBearing);
	headingChange.saveToConfigFile(c, kHeadingChange);
	prefilter.saveToConfigFile(c, kPreFilter);
	loopClosure.saveToConfigFile(c, kLoopClosure);
	smoothedPose.saveToConfigFile(c, kSmoothedPose);
}

void CVSlamParticleFilter::TOptions::registerKnownKeys(config::KnownKeys& k) const
{
	k.addFromOptions(pf, kParticleFilter);
	k.addFromOptions(motion, kMotionModel);
	k.addFromOptions(likelihood, kLikelihood);
	k.addFromOptions(mixture, kMixture);
	k.addFromOptions(kidnap, kKidnap);
	k.addFromOptions(landmarks, kLandmarks);
	k.addFromOptions(visual, kVisual);
	k.addFromOptions(rangeBearing, kRangeBearing);
	k.addFromOptions(headingChange, kHeadingChange);
	k.addFromOptions(prefilter, kPreFilter);
	k.addFromOptions(loopClosure, kLoopClosure);
	k.addFromOptions(smoothedPose, kSmoothedPose);
}
