/** Fuzz target: deserialization of vslam's own observation classes and what
 * the filter does with one. The first input byte picks the class (even:
 * CObservationVisualLandmark, odd: CObservationLandmarkCreated); the rest
 * follows the class header (version byte, fields, end mark). An exception
 * is a clean refusal (the rawlog reader turns it into an InputError naming
 * the entry); a crash, hang, leak or sanitizer report is a finding. */
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <libvslam/obs/registerClasses.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const bool registered = (vslam::registerObservationClasses(), true);
	(void)registered;
	if (size < 1) return 0;
	const std::string name = (data[0] & 1)
		? vslam::CObservationLandmarkCreated::GetRuntimeClassIdStatic().className
		: vslam::CObservationVisualLandmark::GetRuntimeClassIdStatic().className;
	mrpt::io::CMemoryStream buf;
	const uint8_t header = 0x80 | static_cast<uint8_t>(name.size());
	buf.Write(&header, 1);
	buf.Write(name.data(), name.size());
	buf.Write(data + 1, size - 1);
	buf.Seek(0);
	auto arch = mrpt::serialization::archiveFrom(buf);
	mrpt::obs::CObservation::Ptr obs;
	try
	{
		obs = arch.ReadObject<mrpt::obs::CObservation>();
	}
	catch (const std::exception&)
	{
		return 0;
	}
	if (!obs) return 0;
	std::ostringstream text;
	obs->getDescriptionAsText(text);
	(void)obs->exportTxtDataRow();

	// One filter step with it: the pre-filter and the measurement models
	// must take any field values (NaN, inf, huge IDs) without harm.
	vslam::CVSlamParticleFilter::TOptions options;
	options.pf.sampleSize = 10;
	vslam::CVSlamParticleFilter filter(options);
	mrpt::bayes::CParticleFilter pf;
	pf.m_options = options.pf.toMrpt();
	mrpt::obs::CActionCollection acts;
	mrpt::obs::CActionRobotMovement2D move;
	move.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0.01), {});
	move.timestamp = obs->timestamp;
	acts.insert(move);
	mrpt::obs::CSensoryFrame sf;
	sf.insert(obs);
	try
	{
		for (int i = 0; i < 3; i++) pf.executeOn(filter, &acts, &sf);
	}
	catch (const std::exception&)
	{
	}
	return 0;
}
