#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/ReadSensorLabel.h>
#include <mrpt/serialization/CArchive.h>

#include <iomanip>
#include <sstream>

using namespace vslam;

IMPLEMENTS_SERIALIZABLE(CObservationLandmarkCreated, mrpt::obs::CObservation, vslam)

uint8_t CObservationLandmarkCreated::serializeGetVersion() const { return 0; }

void CObservationLandmarkCreated::serializeTo(
	mrpt::serialization::CArchive& out) const
{
	out << timestamp << sensorLabel;
	out << landmarkID << landmarkPoseInRobot.x() << landmarkPoseInRobot.y()
		<< landmarkPoseInRobot.phi();
	for (int r = 0; r < 3; r++)
		for (int c = r; c < 3; c++) out << landmarkPoseInRobotCov(r, c);
	out << NPoints << NViews << sensorPoseOnRobot;
}

void CObservationLandmarkCreated::serializeFrom(
	mrpt::serialization::CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
		{
			double x = 0, y = 0, phi = 0;
			in >> timestamp;
			readSensorLabel(in, sensorLabel);
			in >> landmarkID >> x >> y >> phi;
			landmarkPoseInRobot = mrpt::poses::CPose2D(x, y, phi);
			for (int r = 0; r < 3; r++)
				for (int c = r; c < 3; c++)
				{
					double v = 0;
					in >> v;
					landmarkPoseInRobotCov(r, c) = v;
					landmarkPoseInRobotCov(c, r) = v;
				}
			in >> NPoints >> NViews >> sensorPoseOnRobot;
		}
		break;
		default:
			MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	};
}

void CObservationLandmarkCreated::getDescriptionAsText(std::ostream& o) const
{
	CObservation::getDescriptionAsText(o);
	o << "Visual landmark created\n"
	  << " landmarkID          : " << landmarkID << "\n"
	  << " landmarkPoseInRobot : " << landmarkPoseInRobot
	  << " (dx, dy, dtheta[deg])\n"
	  << " NPoints             : " << NPoints << "\n"
	  << " NViews              : " << NViews << "\n"
	  << " sensorPose          : " << sensorPoseOnRobot << "\n";
}

std::string CObservationLandmarkCreated::exportTxtHeader() const
{
	return "landmarkID dx dy dtheta NPoints NViews";
}

std::string CObservationLandmarkCreated::exportTxtDataRow() const
{
	std::ostringstream s;
	s << std::setprecision(9) << landmarkID << ' ' << landmarkPoseInRobot.x()
	  << ' ' << landmarkPoseInRobot.y() << ' ' << landmarkPoseInRobot.phi()
	  << ' ' << NPoints << ' ' << NViews;
	return s.str();
}
