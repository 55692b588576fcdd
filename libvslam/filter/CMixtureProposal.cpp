#include <libvslam/config/StrictRead.h>
#include <libvslam/filter/CMixtureProposal.h>

#include <algorithm>

using namespace vslam;
using namespace vslam::config;

void CMixtureProposal::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	nominal_proposal = static_cast<Nominal>(readChoice(
		c, s, "nominal_proposal", static_cast<size_t>(nominal_proposal),
		{"motion", "optimal"}));
	dual_ratio = readDouble(c, s, "dual_ratio", dual_ratio, Range::closed(0, 1));
	dual_ratio_max =
		readDouble(c, s, "dual_ratio_max", dual_ratio_max, Range::closed(0, 1));
	dual_only_if_sharper =
		readBool(c, s, "dual_only_if_sharper", dual_only_if_sharper);
}

void CMixtureProposal::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "nominal_proposal",
		std::string(nominal_proposal == Nominal::Motion ? "motion" : "optimal"), 25, 12,
		"motion (the paper's nominal particles) | optimal (motion updated with the frame's measurements)");
	c.write(s, "dual_ratio", dual_ratio, 25, 12,
		"Base share of dual particles, [0,1] (paper: 20 of 200 = 0.1)");
	c.write(s, "dual_ratio_max", dual_ratio_max, 25, 12,
		"Share reached as the explained fraction falls to 0 (= dual_ratio: fixed; both 0: no duals)");
	c.write(s, "dual_only_if_sharper", dual_only_if_sharper, 25, 12,
		"Draw duals only if sharper than the predicted cloud or the cloud misses the measurement");
}

double CMixtureProposal::ratio(double explainedFraction, bool dualUseful) const
{
	if (options.dual_only_if_sharper && !dualUseful) return 0.0;
	const double f = std::clamp(explainedFraction, 0.0, 1.0);
	const double hi = std::max(options.dual_ratio, options.dual_ratio_max);
	return options.dual_ratio + (hi - options.dual_ratio) * (1.0 - f);
}
