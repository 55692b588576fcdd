/** The main of every test binary: GoogleTest's, with OpenCV on one thread.
 *
 * ctest runs the tests as processes side by side, one per core (-j), so the
 * cores are already busy. OpenCV's own thread pool on top of that only adds
 * waiting: one front-end test over 2 laps of images took 5.1 s on one core
 * with one thread, and 6.0 s of wall time and 9.0 s of CPU with the pool on
 * two free cores. The apps the tests start keep OpenCV's default. */
#include <gtest/gtest.h>
#include <opencv2/core/utility.hpp>

int main(int argc, char** argv)
{
	cv::setNumThreads(1);
	::testing::InitGoogleTest(&argc, argv);
	return RUN_ALL_TESTS();
}
