#include <libvslam/obs/CObservationVisualLandmark.h>
#include <libvslam/obs/ReadSensorLabel.h>
#include <mrpt/serialization/CArchive.h>

#include <iomanip>
#include <sstream>

using namespace vslam;

IMPLEMENTS_SERIALIZABLE(CObservationVisualLandmark, mrpt::obs::CObservation, vslam)

uint8_t CObservationVisualLandmark::serializeGetVersion() const { return 3; }

void CObservationVisualLandmark::serializeTo(
	mrpt::serialization::CArchive& out) const
{
	// CObservation does not write its own fields: every class does.
	out << timestamp << sensorLabel;
	out << landmarkID << relPose.x() << relPose.y() << relPose.phi();
	out << ProjErrRMS << NPoints << Slope << sensorPoseOnRobot;
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++) out << relPoseCov(r, c);
	out << Height << SlopeStd;
}

void CObservationVisualLandmark::serializeFrom(
	mrpt::serialization::CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
		case 1:
		case 2:
		case 3:
		{
			double x = 0, y = 0, phi = 0;
			in >> timestamp;
			readSensorLabel(in, sensorLabel);
			in >> landmarkID >> x >> y >> phi;
			relPose = mrpt::poses::CPose2D(x, y, phi);
			in >> ProjErrRMS >> NPoints >> Slope >> sensorPoseOnRobot;
			relPoseCov.setZero();
			if (version >= 1)
				for (int r = 0; r < 3; r++)
					for (int c = 0; c < 3; c++) in >> relPoseCov(r, c);
			Height = 0;
			if (version >= 2) in >> Height;
			SlopeStd = 0;
			if (version >= 3) in >> SlopeStd;
		}
		break;
		default:
			MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	};
}

void CObservationVisualLandmark::getDescriptionAsText(std::ostream& o) const
{
	CObservation::getDescriptionAsText(o);
	o << "Visual landmark measurement\n"
	  << " landmarkID : " << landmarkID << "\n"
	  << " relPose    : " << relPose << " (dx, dy, dtheta[deg])\n"
	  << " ProjErrRMS : " << ProjErrRMS << " px\n"
	  << " NPoints    : " << NPoints << "\n"
	  << " Slope      : " << Slope << " rad (predicted std " << SlopeStd << "; 0: not known)\n"
	  << " Height     : " << Height << " m\n"
	  << " sensorPose : " << sensorPoseOnRobot << "\n"
	  << " relPoseCov : " << relPoseCov.inMatlabFormat() << " (predicted; zero: not known)\n";
}

std::string CObservationVisualLandmark::exportTxtHeader() const
{
	return "landmarkID dx dy dtheta ProjErrRMS NPoints Slope Height";
}

std::string CObservationVisualLandmark::exportTxtDataRow() const
{
	std::ostringstream s;
	s << std::setprecision(9) << landmarkID << ' ' << relPose.x() << ' '
	  << relPose.y() << ' ' << relPose.phi() << ' ' << ProjErrRMS << ' '
	  << NPoints << ' ' << Slope << ' ' << Height;
	return s.str();
}
