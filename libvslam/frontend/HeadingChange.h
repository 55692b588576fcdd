#pragma once
/** \file HeadingChange.h
 * The robot's heading change between two camera images, from the features
 * they share: a visual gyro beside the wheels. Wheel odometry's heading is
 * its weakest part (slip in turns, a wheelbase that is never exact), and the
 * heading error of the stretches between landmarks is most of vSLAM's error
 * while it explores.
 *
 * Model: between the two images the robot turns by theta and moves by a
 * chord of length d (from the odometry) in direction alpha from its start
 * heading: U = (d cos alpha, d sin alpha, theta). The camera sits at its
 * mount M on the robot, so it moves by M^-1 (+) U (+) M, and every feature
 * seen in both images satisfies that motion's epipolar constraint. No
 * odometry heading enters the estimate, only the distance, whose error
 * changes the parallax of near points and moves theta little. A
 * differential drive going forward puts the chord between its start and
 * end headings whatever it did in between (a circular arc: exactly
 * theta/2; a turn, then a straight: theta), so alpha has the prior
 * N(theta/2, theta^2/4 + 1 deg^2): both headings one std away, since a
 * robot that turns in place and then drives (or the other way round) puts
 * the chord at one of them, plus a little slip (a chord that odometry says
 * went backwards: the same, reversed). With the camera off the robot's
 * axis a turn in place still moves it, so the constraint holds there too
 * (weakly: the camera then moves sideways, and its epipolar lines lie
 * along the shift a turn gives the points); a camera that does not move at
 * all is handled as a pure rotation.
 *
 * Estimate: each match's change of bearing about the robot's vertical axis
 * votes for theta (the densest window of votes gives the start,
 * independently of odometry); a fine search of the truncated squared
 * Sampson distance around it on the arc (alpha = theta/2), then
 * Gauss-Newton for theta on the arc over the matches within `inlierPx` of
 * the model, the inliers chosen again after each step. The fit is kept
 * only if its inliers' bearing changes (their median; votes ignore
 * parallax) differ from theta by no more than the parallax the camera's
 * translation can give at `minDepth`: beyond that the fit explains the
 * matches with a motion the robot did not make, e.g. a slip the odometry
 * missed, near a surface, which the epipolar distance alone cannot tell
 * from a turn. The predicted std
 * is that of the least-squares fit (the inliers' residual scatter over the
 * sum of their squared derivatives) plus the chord direction's prior
 * spread carried through the fit's sensitivity to it. The images are not
 * asked for alpha: a few centimetres of travel give its direction so
 * poorly that a fit of both trusted its alpha 2.5 times too much and theta
 * with it.
 */
#include <libvslam/frontend/ImageFeatures.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>
#include <optional>

namespace vslam
{
struct THeadingEstimationOptions
{
	double matchRatio = 0.8;  //!< Lowe's ratio test
	int minInliers = 20;  //!< matches that must fit the model
	double inlierPx = 1.5;  //!< Sampson distance of an inlier, pixels
	double maxTurn = 45 * M_PI / 180;  //!< largest heading change looked for, rad
	/** Nearest depth a scene point may have, m: bounds the parallax by
	 * which a match's bearing change may differ from the heading change. */
	double minDepth = 0.2;
};

struct HeadingChangeEstimate
{
	double dphi = 0;  //!< heading change from the first image to the second, rad
	double stdDphi = 0;  //!< its predicted std, rad
	int inliers = 0, matches = 0;
	double rmsPx = 0;  //!< RMS Sampson distance of the inliers, pixels
};

/** The camera's motion between the two images for one (theta, alpha),
 * built once to score many matches (PlanarEpipolarModel::motion). */
struct EpipolarMotion
{
	/** The essential matrix E = [t]x R (X1 = R X2 + t) and its derivatives,
	 * by theta, alpha and the two wobble angles (right perturbations of R
	 * about PlanarEpipolarModel::wobbleAxes()). */
	Eigen::Matrix3d E, dE_dtheta, dE_dalpha, dE_dwobble[2];
	/** A camera that does not move (on the robot's axis, turning in place):
	 * the rotation, its derivatives, and those at theta = 0. */
	bool still = false;
	Eigen::Matrix3d R, dR_dtheta, dR_dwobble[2], R0, dR0_dtheta;
	double translation = 0;  //!< of the camera, m (0: still)
};

/** The epipolar geometry of one robot motion: the residual of a match as
 * a function of the heading change theta and the chord's direction alpha.
 * Rays are unit-depth rays of undistorted pixels in each image's camera
 * frame (PinholeCamera::ray). */
class PlanarEpipolarModel
{
   public:
	/** `mount`: the camera on the robot (camera coordinates to robot
	 * coordinates); `chord`: the distance the robot moved, m (negative:
	 * backwards, so alpha stays near the heading). */
	PlanarEpipolarModel(const mrpt::poses::CPose3D& mount, double chord);

	/** The second camera in the first one's frame: X1 = R X2 + t, and the
	 * derivatives of R and t by theta and of t by alpha. */
	void cameraMotion(double theta, double alpha, Eigen::Matrix3d& R, Eigen::Vector3d& t,
		Eigen::Matrix3d* dR_dtheta = nullptr, Eigen::Vector3d* dt_dtheta = nullptr,
		Eigen::Vector3d* dt_dalpha = nullptr) const;

	/** The camera's motion for (theta, alpha), its rotation followed by
	 * `wobble` (X1 = R wobble X2 + t): the camera's pitch and roll change
	 * between the two images as the floor shakes it, which a planar robot
	 * motion does not hold. */
	EpipolarMotion motion(double theta, double alpha, const Eigen::Matrix3d& wobble = Eigen::Matrix3d::Identity()) const;

	/** Two unit axes, in the second camera's frame, perpendicular to the
	 * robot's vertical and to each other: the directions a wobble can
	 * turn the camera without looking like a heading change. */
	const Eigen::Matrix3d& wobbleAxes() const { return m_wobbleAxes; }

	/** Signed Sampson distance of rays r1 (first image) and r2 (second)
	 * under `m`, in normalized image units (times the focal length:
	 * pixels), and its derivatives by theta and alpha. Where the camera does
	 * not move, the distance of r1 from R r2 across the direction in which
	 * the rotation moves the point. */
	static double residual(const EpipolarMotion& m, const Eigen::Vector3d& r1, const Eigen::Vector3d& r2,
		double* dTheta = nullptr, double* dAlpha = nullptr, double* dWobble = nullptr);
	/** The same for (theta, alpha). */
	double residual(const Eigen::Vector3d& r1, const Eigen::Vector3d& r2, double theta, double alpha,
		double* dTheta = nullptr, double* dAlpha = nullptr) const
	{
		return residual(motion(theta, alpha), r1, r2, dTheta, dAlpha);
	}

	/** The prior std of alpha around theta/2 for heading change theta. */
	static double chordDirectionStd(double theta);

   private:
	Eigen::Matrix3d m_Rm;  //!< mount rotation (camera to robot)
	Eigen::Vector3d m_tm;  //!< camera centre on the robot
	double m_chord;
	Eigen::Matrix3d m_wobbleAxes;  //!< columns 0 and 1 (2: the robot's vertical)
};

/** The heading change from `first` to `second`, or nullopt when too few
 * matches fit one (e.g. unrelated images, a blank wall, motion blur). */
std::optional<HeadingChangeEstimate> estimateHeadingChange(const ImageFeatures& first, const ImageFeatures& second,
	const mrpt::poses::CPose3D& mount, double chord, const THeadingEstimationOptions& settings);

/** Measures the heading change between consecutive images of a camera, for
 * the filter to fuse into the odometry ([vslam_heading_change]). */
class CHeadingChangeEstimator
{
   public:
	/** INI section [vslam_heading_measurement]. Not in the paper. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_heading_measurement";

		bool enabled = true;  //!< measure and emit CObservationHeadingChange
		int min_inliers = 20;  //!< matches that must fit the motion
		double inlier_px = 1.5;  //!< epipolar distance of an inlier, px

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	/** `matchRatio`: the features' ratio test. */
	CHeadingChangeEstimator(const TOptions& options, double matchRatio);

	/** estimateHeadingChange() with these options. */
	std::optional<HeadingChangeEstimate> estimate(const ImageFeatures& first, const ImageFeatures& second,
		const mrpt::poses::CPose3D& mount, double chord) const
	{
		return estimateHeadingChange(first, second, mount, chord, m_settings);
	}

   private:
	THeadingEstimationOptions m_settings;
};
}  // namespace vslam
