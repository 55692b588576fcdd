/** The main of every test binary: GoogleTest's, with OpenCV on one thread.
 *
 * ctest runs the tests as processes side by side, one per core (-j), so the
 * cores are already busy. OpenCV's own thread pool on top of that only adds
 * waiting: on two free cores, one front-end test over 2 laps of images took
 * 4.7 s of wall time and of CPU with one thread, and 6.0 s of wall time and
 * 9.0 s of CPU with the pool (doc/reliability.md). The apps the tests start
 * keep OpenCV's default. */
#include <gtest/gtest.h>
#include <opencv2/core/utility.hpp>

int main(int argc, char** argv)
{
	cv::setNumThreads(1);
	::testing::InitGoogleTest(&argc, argv);
	return RUN_ALL_TESTS();
}
