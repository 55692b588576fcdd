#include <libvslam/world/FloorPlanFile.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace vslam::world
{
namespace
{
std::string num(double v)
{
	char buf[32];
	std::snprintf(buf, sizeof buf, "%.4f", v);
	std::string s = buf;
	while (s.back() == '0') s.pop_back();
	if (s.back() == '.') s.pop_back();
	return s == "-0" ? "0" : s;
}

std::string pt(const Eigen::Vector2d& p) { return num(p[0]) + " " + num(p[1]); }

std::string relative(const std::string& file, const std::string& textureDir)
{
	const std::string prefix = textureDir.empty() || textureDir.back() == '/' ? textureDir : textureDir + "/";
	return !prefix.empty() && file.compare(0, prefix.size(), prefix) == 0 ? file.substr(prefix.size()) : file;
}

std::string spec(const FloorPlan& plan, const TextureRef& t, const std::string& textureDir)
{
	if (t.material >= 0) return plan.materials.at(static_cast<size_t>(t.material)).name;
	std::string s = relative(t.file, textureDir);
	if (t.u0 != 0 || t.v0 != 0 || t.u1 != 1 || t.v1 != 1)
		s += "@" + num(t.u0) + "," + num(t.v0) + "," + num(t.u1) + "," + num(t.v1);
	return t.mirrored ? s + "~" : s;
}

/** Degrees in (-180, 180]. */
double deg(double rad)
{
	double d = std::fmod(rad * 180 / M_PI, 360.0);
	if (d <= -180) d += 360;
	if (d > 180) d -= 360;
	return d;
}

/** The materials some surface uses (a plan may define more). */
std::vector<bool> usedMaterials(const FloorPlan& plan)
{
	std::vector<bool> used(plan.materials.size(), false);
	const auto use = [&](const TextureRef& t) {
		if (t.material >= 0) used[static_cast<size_t>(t.material)] = true;
	};
	if (plan.hasFloorTexture) use(plan.floor);
	if (plan.hasCeilingTexture) use(plan.ceiling);
	if (plan.skirtingHeight > 0) use(plan.skirting);
	for (const Wall& w : plan.walls) use(w.front), use(w.back);
	for (const Opening& o : plan.openings) use(o.texture);
	for (const FloorArea& a : plan.floorAreas) use(a.texture);
	for (const Box& b : plan.boxes) use(b.texture);
	for (const Picture& q : plan.pictures) use(q.texture);
	for (const Door& d : plan.doors) use(d.texture);
	return used;
}

void writeSurfaces(const FloorPlan& plan, const std::string& dir, std::ostream& out)
{
	out << "ceiling_height " << num(plan.ceilingHeight) << "\n";
	const std::vector<bool> used = usedMaterials(plan);
	for (size_t i = 0; i < plan.materials.size(); i++)
	{
		if (!used[i]) continue;
		const Material& m = plan.materials[i];
		out << "material " << m.name << " " << relative(m.file, dir) << " " << num(m.tileWidth) << " "
			<< num(m.tileHeight);
		if (m.tint != std::array<double, 3>{1, 1, 1})
			out << " tint=" << num(std::round(m.tint[0] * 255)) << "," << num(std::round(m.tint[1] * 255)) << ","
				<< num(std::round(m.tint[2] * 255));
		if (m.contrast != 1) out << " contrast=" << num(m.contrast);
		out << "\n";
	}
	if (plan.hasFloorTexture) out << "floor " << spec(plan, plan.floor, dir) << "\n";
	for (const FloorArea& a : plan.floorAreas) out << "floor " << spec(plan, a.texture, dir) << " " << pt(a.lo) << " " << pt(a.hi) << "\n";
	if (plan.hasCeilingTexture) out << "ceiling " << spec(plan, plan.ceiling, dir) << "\n";
	if (plan.skirtingHeight > 0) out << "skirting " << num(plan.skirtingHeight) << " " << spec(plan, plan.skirting, dir) << "\n";
}

void writeWalls(const FloorPlan& plan, const std::string& dir, std::ostream& out)
{
	for (const Wall& w : plan.walls)
	{
		out << "wall " << pt(w.a) << " " << pt(w.b) << " " << num(w.thickness) << " " << spec(plan, w.front, dir);
		if (w.hasBack) out << " " << spec(plan, w.back, dir);
		out << "\n";
	}
	for (const Opening& o : plan.openings)
	{
		const Wall& w = plan.walls[o.wall];
		const Eigen::Vector2d a = alongWall(w, o.s0), b = alongWall(w, o.s1);
		if (o.kind == Opening::Kind::Window)
		{
			out << "window " << pt(a) << " " << pt(b) << " " << num(o.z0) << " " << num(o.z1) << " "
				<< spec(plan, o.texture, dir) << "\n";
			continue;
		}
		// The leaf is hinged at the first point.
		out << "doorway " << (o.hingeAtS0 ? pt(a) + " " + pt(b) : pt(b) + " " + pt(a)) << " " << num(o.z1);
		if (o.hasLeaf) out << " " << spec(plan, o.texture, dir) << (o.leafToFront ? " front" : " back");
		out << "\n";
	}
}
}  // namespace

std::string floorPlanText(const FloorPlan& plan, const std::string& textureDir)
{
	std::ostringstream out;
	writeSurfaces(plan, textureDir, out);
	writeWalls(plan, textureDir, out);
	for (const Furniture& f : plan.furniture)
	{
		out << "furniture " << pt(f.centre) << " " << num(deg(f.facing)) << " " << f.item->name;
		if (std::abs(f.elevation - f.item->elevation) > 1e-9) out << " " << num(f.elevation);
		out << "\n";
	}
	for (const Box& b : plan.boxes)
		out << "box " << pt(b.centre) << " " << num(deg(b.yaw)) << " " << num(b.sizeX) << " " << num(b.sizeY) << " "
			<< num(b.height) << " " << spec(plan, b.texture, textureDir) << "\n";
	for (const Picture& q : plan.pictures)
		out << (q.framed ? "picture " : "panel ") << pt(q.a) << " " << pt(q.b) << " " << num(q.z0) << " " << num(q.z1) << " "
			<< spec(plan, q.texture, textureDir) << "\n";
	for (const Door& d : plan.doors) out << "door " << pt(d.a) << " " << pt(d.b) << " " << spec(plan, d.texture, textureDir) << "\n";
	return out.str();
}
}  // namespace vslam::world
