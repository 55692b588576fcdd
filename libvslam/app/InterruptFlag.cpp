#include <libvslam/app/InterruptFlag.h>

#include <csignal>

namespace vslam
{
namespace
{
volatile std::sig_atomic_t g_raised = 0;
struct sigaction g_oldInt, g_oldTerm;

void onSignal(int) { g_raised = 1; }
}  // namespace

InterruptFlag::InterruptFlag()
{
	g_raised = 0;
	struct sigaction sa = {};
	sa.sa_handler = onSignal;
	sigemptyset(&sa.sa_mask);
	sa.sa_flags = SA_RESETHAND;  // a second signal terminates
	sigaction(SIGINT, &sa, &g_oldInt);
	sigaction(SIGTERM, &sa, &g_oldTerm);
}

InterruptFlag::~InterruptFlag()
{
	sigaction(SIGINT, &g_oldInt, nullptr);
	sigaction(SIGTERM, &g_oldTerm, nullptr);
}

bool InterruptFlag::raised() const { return g_raised != 0; }
}  // namespace vslam
