#pragma once
namespace vslam
{
/** Registers all vslam observation classes (idempotent). It already runs when
 * libvslam_obs is loaded; calling it explicitly also keeps the linker from
 * dropping the library. */
void registerObservationClasses();
}  // namespace vslam
