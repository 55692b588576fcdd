#pragma once
/** \file InterruptFlag.h
 * SIGINT / SIGTERM end a run cleanly: while an InterruptFlag lives, those
 * signals only raise a flag that the run loop polls, so outputs and the
 * summary are written for the steps done. A second signal terminates at
 * once. (Signal handlers can only reach static state: this is the one
 * process-wide flag in vslam.) */
namespace vslam
{
class InterruptFlag
{
   public:
	InterruptFlag();
	~InterruptFlag();
	InterruptFlag(const InterruptFlag&) = delete;
	InterruptFlag& operator=(const InterruptFlag&) = delete;
	bool raised() const;
};
}  // namespace vslam
