#pragma once
/** \file RawlogWriting.h
 * Writes (action, sensory frame) pairs as a gzip rawlog in MRPT's
 * actions/sensory-frames format, which rbpf-slam, kf-slam and rawlog-edit
 * read. */
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <string>
#include <utility>
#include <vector>

namespace vslam
{
using ActionFramePair =
	std::pair<mrpt::obs::CActionCollection::Ptr, mrpt::obs::CSensoryFrame::Ptr>;

void writeActionFrameRawlog(
	const std::string& file, const std::vector<ActionFramePair>& steps);

/** Files that go with a rawlog: "<dir>/<name>.rawlog[.gz]" ->
 * "<dir>/<name><suffix>", e.g. suffix "_groundtruth.tum". */
std::string siblingFile(const std::string& rawlogFile, const std::string& suffix);
}  // namespace vslam
