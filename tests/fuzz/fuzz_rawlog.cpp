/** Fuzz target: rawlog reading (both formats, plain or gzip), the
 * deserialization of vslam's observation classes, and the filter on what
 * was read (10 particles). Any outcome but a run or an InputError is a
 * finding. */
#include <libvslam/core/InputError.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/obs/registerClasses.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <tests/fuzz/FuzzInput.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const bool registered = (vslam::registerObservationClasses(), true);
	(void)registered;
	static const std::string file = vslam::fuzz::scratchPath("input.rawlog");
	vslam::fuzz::writeBytes(file, data, size);
	try
	{
		vslam::CRawlogReader reader(file);
		vslam::TVSlamFilterOptions options;
		options.pf.sampleSize = 10;
		vslam::CVSlamParticleFilter filter(options);
		mrpt::bayes::CParticleFilter pf;
		pf.m_options = options.pf.toMrpt();
		vslam::RawlogStep step;
		for (int n = 0; n < 2000 && reader.next(step); n++)
		{
			try
			{
				pf.executeOn(filter, step.action.get(), step.sf.get());
			}
			catch (const std::exception&)
			{
				// The app's rule: bad input found by the filter (wrapped by
				// MRPT) is an input error; anything else is a finding.
				if (filter.takeInputError().empty()) throw;
				return 0;
			}
		}
	}
	catch (const vslam::InputError&)
	{
	}
	return 0;
}
