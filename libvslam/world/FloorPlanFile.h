#pragma once
/** \file FloorPlanFile.h
 * The world file of the rendered simulator: one item per line, '#' starts
 * a comment, lengths in metres, angles in degrees.
 *
 *     ceiling_height H
 *     material  NAME FILE TILE_W TILE_H [tint=R,G,B] [contrast=C]
 *     floor     TEXTURE [X0 Y0 X1 Y1]
 *     ceiling   TEXTURE
 *     skirting  HEIGHT TEXTURE
 *     wall      X1 Y1 X2 Y2 THICKNESS FRONT_TEXTURE [BACK_TEXTURE]
 *     doorway   X1 Y1 X2 Y2 HEIGHT [LEAF_TEXTURE [front|back]]
 *     window    X1 Y1 X2 Y2 Z0 Z1 VIEW_TEXTURE
 *     furniture X Y FACING NAME [ELEVATION]
 *     box       X Y YAW SIZE_X SIZE_Y HEIGHT TEXTURE
 *     picture   X1 Y1 X2 Y2 Z0 Z1 TEXTURE
 *     panel     X1 Y1 X2 Y2 Z0 Z1 TEXTURE
 *     door      X1 Y1 X2 Y2 TEXTURE
 *
 * TEXTURE is a photograph, relative to the texture folder (or absolute;
 * a member of a package's archive is named through it: AssetArchive.h),
 * optionally followed by "@U0,V0,U1,V1" (the part of it used, as
 * fractions) and by "~" (mirrored left-right); or the NAME of a material
 * defined above it, tiled at its real size. A material's tint is its
 * paint colour (0-255 per channel), its contrast scales the photograph's
 * texture around its mean (0-1).
 *
 * A floor with a rectangle covers only that rectangle (a room's parquet
 * over the base floor). A doorway and a window lie on a wall's centre
 * line and cut through it: a doorway from the floor to HEIGHT (its open
 * leaf, if textured, hinged at X1 Y1 and standing at right angles on the
 * wall's front side, or its back), a window from Z0 to Z1 with the view photograph outside, behind
 * the wall's back face. FURNITURE is a catalogue model (FurnitureCatalog.h,
 * `vslam-simul --list-furniture`) with the centre of its footprint at X Y
 * and its front facing FACING degrees; ELEVATION overrides the catalogue's.
 * A picture hangs in a frame on the wall face left of X1 Y1 -> X2 Y2; a
 * panel covers the wall there without one (tiles behind a counter).
 *
 * Any error (unknown item or material, wrong field count, bad number,
 * missing texture, degenerate geometry, a doorway or window that is not on
 * a wall, two openings that overlap, furniture or a box through a wall, a
 * world without walls) is an InputError naming the file and line.
 */
#include <libvslam/world/FloorPlan.h>

#include <string>

namespace vslam::world
{
FloorPlan parseFloorPlan(
	const std::string& text, const std::string& fileName, const std::string& textureDir);

FloorPlan loadFloorPlan(const std::string& file, const std::string& textureDir);

/** The world file text of a plan (the generator's homes written out for
 * reading and editing); parseFloorPlan reads it back to the same plan. */
std::string floorPlanText(const FloorPlan& plan, const std::string& textureDir);
}  // namespace vslam::world
