#include <libvslam/core/ExceptionText.h>
#include <libvslam/core/InputError.h>
#include <libvslam/frontend/ImagesToMeasurements.h>
#include <mrpt/obs/CObservationImage.h>

#include <filesystem>

using namespace vslam;

ImagesToMeasurementsResult vslam::replaceImagesWithMeasurements(
	CVisualFrontEnd& frontEnd, mrpt::obs::CSensoryFrame& frame, const mrpt::poses::CPose2D& odometryPose,
	const std::string& where)
{
	ImagesToMeasurementsResult r;
	std::vector<mrpt::obs::CObservation::Ptr> kept, added;
	for (auto it = frame.begin(); it != frame.end(); ++it)
	{
		const auto image = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(*it);
		if (!image)
		{
			kept.push_back(*it);
			continue;
		}
		const std::string name = image->image.isExternallyStored()
			? "image '" + image->image.getExternalStorageFileAbsolutePath() + "'"
			: "image";
		const std::string what = where + ", " + name;
		if (image->image.isExternallyStored() &&
			!std::filesystem::is_regular_file(image->image.getExternalStorageFileAbsolutePath()))
			throw InputError(what + ": file not found");
		try
		{
			image->image.forceLoad();
		}
		catch (const std::exception& e)
		{
			throw InputError(what + ": cannot be read: " + exceptionText(e));
		}
		CVisualFrontEnd::Output out;
		try
		{
			out = frontEnd.process(*image, odometryPose, what);
		}
		catch (const std::invalid_argument& e)
		{
			throw InputError(e.what());
		}
		catch (const std::exception& e)
		{
			// Not the input's fault: say where, and do not call it unreadable.
			throw std::runtime_error(what + ": the front-end failed on it: " + exceptionText(e));
		}
		image->image.unload();  // external images: free the pixels again
		r.images++;
		for (const auto& c : out.created) added.push_back(c);
		for (const auto& m : out.measurements) added.push_back(m);
		for (const auto& h : out.headingChanges) added.push_back(h);
		r.headingChanges += out.headingChanges.size();
		r.created += out.created.size();
		r.measurements += out.measurements.size();
		r.pruned += out.pruned.size();
	}
	if (r.images == 0) return r;
	frame.clear();
	for (const auto& o : kept) frame.insert(o);
	for (const auto& o : added) frame.insert(o);
	return r;
}
