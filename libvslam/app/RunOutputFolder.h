#pragma once
/** \file RunOutputFolder.h
 * The output folder of one vslam run. Created if needed and checked
 * writable before the run; the outputs an earlier run left there (every
 * file name vslam writes, and temporaries of a run that died) are removed,
 * so a folder never mixes two runs' files. Files of other programs stay.
 */
#include <string>
#include <vector>

namespace vslam
{
class RunOutputFolder
{
   public:
	/** Every file a vslam run can write. */
	static const std::vector<std::string>& outputNames();

	/** Creates the folder; throws OutputError if it cannot, or cannot be
	 * written. */
	explicit RunOutputFolder(std::string dir);

	/** Removes what an earlier run left; throws OutputError if a file
	 * cannot be removed. */
	void clearEarlierOutputs() const;

	/** Sets aside disk space for the summary (best effort): a disk that
	 * fills up during the run still gets the summary saying so. */
	void reserveSummarySpace() const;
	/** Gives that space back, just before the summary is written. */
	void releaseSummarySpace() const;

	std::string file(const std::string& name) const;
	const std::string& dir() const { return m_dir; }

   private:
	std::string m_dir;
};

/** An identifier of a run from what determines its outputs (the effective
 * configuration without the output folder, the rawlog's path, size and
 * time, the seed): a rerun that must repeat a run gets its identifier, so
 * same-seed outputs stay byte-identical; any other run gets another. */
std::string makeRunId(const std::string& effectiveConfigText, const std::string& rawlogFile, uint64_t seed);
}  // namespace vslam
