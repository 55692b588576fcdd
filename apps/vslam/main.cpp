/** vslam: the vSLAM filter over an MRPT rawlog (see CVSlamApp.h). */
#include <libvslam/app/CVSlamApp.h>

int main(int argc, const char** argv) { return vslam::CVSlamApp().main(argc, argv); }
