#include <libvslam/batch/BatchRunner.h>
#include <libvslam/batch/BatchTask.h>

#include <atomic>
#include <mutex>
#include <thread>

namespace vslam::batch
{
namespace
{
/** Runs the tasks of one kind with `jobs` workers. */
void runPhase(const BatchPlan& plan, Task::Kind kind, const std::string& binDir, BatchOutcome& outcome,
	size_t& finished, size_t total, const std::function<void(const std::string&)>& report)
{
	std::vector<const Task*> tasks;
	for (const auto& t : plan.tasks)
		if (t.kind == kind) tasks.push_back(&t);
	std::atomic<size_t> next{0};
	std::mutex lock;
	const auto worker = [&]() {
		for (size_t i; (i = next++) < tasks.size();)
		{
			const TaskOutcome r = runTask(plan, *tasks[i], binDir);
			const std::lock_guard<std::mutex> guard(lock);
			finished++;
			(r.skipped ? outcome.skipped : r.ok ? outcome.done : outcome.failed)++;
			report("[" + std::to_string(finished) + "/" + std::to_string(total) + "] " + tasks[i]->id + ": " +
				(r.ok ? "" : "FAILED: ") + r.message);
		}
	};
	std::vector<std::thread> pool;
	for (int j = 0; j < plan.jobs; j++) pool.emplace_back(worker);
	for (auto& t : pool) t.join();
}
}  // namespace

BatchOutcome runBatch(
	const BatchPlan& plan, const std::string& binDir, const std::function<void(const std::string& line)>& report)
{
	BatchOutcome outcome;
	size_t finished = 0;
	for (const Task::Kind kind : {Task::Kind::Render, Task::Kind::Peer, Task::Kind::Run})
		runPhase(plan, kind, binDir, outcome, finished, plan.tasks.size(), report);
	return outcome;
}
}  // namespace vslam::batch
