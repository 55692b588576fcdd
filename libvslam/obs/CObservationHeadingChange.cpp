#include <libvslam/obs/CObservationHeadingChange.h>
#include <libvslam/obs/ReadSensorLabel.h>
#include <mrpt/serialization/CArchive.h>

#include <iomanip>
#include <sstream>

using namespace vslam;

IMPLEMENTS_SERIALIZABLE(CObservationHeadingChange, mrpt::obs::CObservation, vslam)

uint8_t CObservationHeadingChange::serializeGetVersion() const { return 0; }

void CObservationHeadingChange::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << timestamp << sensorLabel << previousTimestamp << dphi << stdDphi << NMatches << NInliers << rmsPx
		<< sensorPoseOnRobot;
}

void CObservationHeadingChange::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
			in >> timestamp;
			readSensorLabel(in, sensorLabel);
			in >> previousTimestamp >> dphi >> stdDphi >> NMatches >> NInliers >> rmsPx >> sensorPoseOnRobot;
			break;
		default:
			MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	};
}

void CObservationHeadingChange::getDescriptionAsText(std::ostream& o) const
{
	CObservation::getDescriptionAsText(o);
	o << "Heading change between two images\n"
	  << " since      : " << mrpt::Clock::toDouble(previousTimestamp) << " (UNIX s)\n"
	  << " dphi       : " << dphi << " rad (predicted std " << stdDphi << ")\n"
	  << " NMatches   : " << NMatches << "\n"
	  << " NInliers   : " << NInliers << "\n"
	  << " rmsPx      : " << rmsPx << " px\n"
	  << " sensorPose : " << sensorPoseOnRobot << "\n";
}

std::string CObservationHeadingChange::exportTxtHeader() const
{
	return "since dphi stdDphi NMatches NInliers rmsPx";
}

std::string CObservationHeadingChange::exportTxtDataRow() const
{
	std::ostringstream s;
	s << std::setprecision(17) << mrpt::Clock::toDouble(previousTimestamp) << std::setprecision(9) << ' ' << dphi
	  << ' ' << stdDphi << ' ' << NMatches << ' ' << NInliers << ' ' << rmsPx;
	return s.str();
}
