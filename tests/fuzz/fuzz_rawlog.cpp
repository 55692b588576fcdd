/** Fuzz target: rawlog reading (both formats, plain or gzip), the
 * deserialization of vslam's observation classes, and the filter on what
 * was read (10 particles). Any outcome but a run or an InputError is a
 * finding. The reader's isolated check (a child process reads the file
 * first) runs with tighter limits than the apps' defaults, to stay within
 * the fuzzer's 10 s per input; scripts/fuzz.sh lifts libFuzzer's malloc
 * limit for this target, since the child's memory is bounded by the check
 * and a libFuzzer hook firing inside the child would save a false finding. */
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
		vslam::TIsolatedReadOptions limits;
		limits.maxSecondsPerEntry = 4;
		limits.maxBytesPerEntry = uint64_t(1) << 30;
		vslam::CRawlogReader reader(file, limits);
		vslam::CVSlamParticleFilter::TOptions options;
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
