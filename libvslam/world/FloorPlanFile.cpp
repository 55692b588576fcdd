#include <libvslam/core/InputError.h>
#include <libvslam/world/AssetArchive.h>
#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/WorldChecks.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace vslam::world
{
namespace
{
constexpr double kDeg = M_PI / 180;

/** Texture specs already checked, so an archive is opened once per spec. */
using AssetCache = std::map<std::string, bool>;

class LineParser
{
   public:
	LineParser(const std::string& file, int line, std::vector<std::string> fields, const std::string& textureDir,
		const FloorPlan& plan, AssetCache& assets)
		: m_file(file), m_line(line), m_fields(std::move(fields)), m_textureDir(textureDir), m_plan(plan),
		  m_assets(assets)
	{
	}

	[[noreturn]] void fail(const std::string& what) const
	{
		throw InputError("world file '" + m_file + "' line " + std::to_string(m_line) + ": " + what);
	}

	const std::string& item() const { return m_fields[0]; }
	const std::string& field(size_t i) const { return m_fields.at(i); }
	size_t size() const { return m_fields.size(); }
	int line() const { return m_line; }

	void expectFields(size_t minArgs, size_t maxArgs, const char* syntax) const
	{
		const size_t n = m_fields.size() - 1;
		if (n < minArgs || n > maxArgs)
			fail("'" + item() + "' takes " + syntax + " (" + std::to_string(n) + " fields given)");
	}

	double number(size_t i, const char* name) const
	{
		const std::string& s = m_fields.at(i);
		size_t used = 0;
		double v = 0;
		try
		{
			v = std::stod(s, &used);
		}
		catch (const std::exception&)
		{
			used = 0;
		}
		if (used != s.size() || !std::isfinite(v) || std::abs(v) > 1e4)
			fail(std::string("bad ") + name + " '" + s + "' (a finite number of at most 1e4 is expected)");
		return v;
	}

	double positive(size_t i, const char* name) const
	{
		const double v = number(i, name);
		if (v <= 0) fail(std::string(name) + " must be positive, got '" + m_fields[i] + "'");
		return v;
	}

	Eigen::Vector2d point(size_t i) const { return {number(i, "x"), number(i + 1, "y")}; }

	void distinct(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const
	{
		if ((b - a).norm() < 1e-3) fail("'" + item() + "' has zero length");
	}

	/** An asset path under the texture folder that exists. */
	std::string asset(const std::string& spec) const
	{
		const std::filesystem::path p = std::filesystem::path(spec).is_absolute()
			? std::filesystem::path(spec)
			: std::filesystem::path(m_textureDir) / spec;
		auto it = m_assets.find(p.string());
		if (it == m_assets.end()) it = m_assets.emplace(p.string(), !spec.empty() && locateAsset(p.string())).first;
		if (!it->second) fail("unknown texture '" + spec + "' (no file or archive member " + p.string() + ")");
		return p.string();
	}

	TextureRef texture(size_t i) const
	{
		std::string spec = m_fields.at(i);
		TextureRef t;
		for (size_t m = 0; m < m_plan.materials.size(); m++)
			if (m_plan.materials[m].name == spec)
			{
				t.material = static_cast<int>(m);
				return t;
			}
		if (!spec.empty() && spec.back() == '~') t.mirrored = true, spec.pop_back();
		const auto at = spec.find('@');
		if (at != std::string::npos)
		{
			const std::vector<double> f = fractions(spec.substr(at));
			t.u0 = f[0], t.v0 = f[1], t.u1 = f[2], t.v1 = f[3];
			spec.resize(at);
		}
		t.file = asset(spec);
		return t;
	}

   private:
	std::string m_file;
	int m_line;
	std::vector<std::string> m_fields;
	std::string m_textureDir;
	const FloorPlan& m_plan;
	AssetCache& m_assets;

	std::vector<double> fractions(const std::string& part) const
	{
		std::vector<double> f;
		std::stringstream ss(part.substr(1));
		for (std::string s; std::getline(ss, s, ',');)
		{
			size_t used = 0;
			double v = -1;
			try
			{
				v = std::stod(s, &used);
			}
			catch (const std::exception&)
			{
				used = 0;
			}
			if (used != s.size() || !(v >= 0 && v <= 1))
				fail("bad texture part '" + part + "' (expected @U0,V0,U1,V1 in [0, 1])");
			f.push_back(v);
		}
		if (f.size() != 4 || f[2] <= f[0] || f[3] <= f[1])
			fail("bad texture part '" + part + "' (expected @U0,V0,U1,V1 with U0<U1, V0<V1)");
		return f;
	}
};

void parseMaterial(const LineParser& p, FloorPlan& plan)
{
	p.expectFields(4, 6, "NAME FILE TILE_W TILE_H [tint=R,G,B] [contrast=C]");
	Material m;
	m.name = p.field(1);
	if (m.name.find_first_of("./@~") != std::string::npos) p.fail("material name '" + m.name + "' may not contain . / @ ~");
	for (const Material& other : plan.materials)
		if (other.name == m.name) p.fail("material '" + m.name + "' is defined twice (first on line " + std::to_string(other.line) + ")");
	m.file = p.asset(p.field(2));
	m.tileWidth = p.positive(3, "tile width");
	m.tileHeight = p.positive(4, "tile height");
	for (size_t i = 5; i < p.size(); i++)
	{
		const std::string& kv = p.field(i);
		double r = -1, g = -1, b = -1, c = -1;
		char end = 0;
		if (std::sscanf(kv.c_str(), "tint=%lf,%lf,%lf%c", &r, &g, &b, &end) == 3 && r >= 0 && r <= 255 && g >= 0 &&
			g <= 255 && b >= 0 && b <= 255)
			m.tint = {r / 255, g / 255, b / 255};
		else if (std::sscanf(kv.c_str(), "contrast=%lf%c", &c, &end) == 1 && c >= 0 && c <= 1)
			m.contrast = c;
		else
			p.fail("bad material option '" + kv + "' (expected tint=R,G,B in 0..255 or contrast=C in 0..1)");
	}
	m.line = p.line();
	plan.materials.push_back(m);
}

void parseFloor(const LineParser& p, FloorPlan& plan)
{
	p.expectFields(1, 5, "TEXTURE [X0 Y0 X1 Y1]");
	if (p.size() == 2)
	{
		plan.floor = p.texture(1);
		plan.hasFloorTexture = true;
		return;
	}
	if (p.size() != 6) p.fail("'floor' takes TEXTURE [X0 Y0 X1 Y1] (" + std::to_string(p.size() - 1) + " fields given)");
	FloorArea a;
	a.texture = p.texture(1);
	a.lo = p.point(2), a.hi = p.point(4);
	if (a.hi[0] <= a.lo[0] || a.hi[1] <= a.lo[1]) p.fail("floor area needs X0 < X1 and Y0 < Y1");
	a.line = p.line();
	plan.floorAreas.push_back(a);
}

/** A doorway or window: where on which wall it is. */
void placeOpening(const LineParser& p, const FloorPlan& plan, const Eigen::Vector2d& a, const Eigen::Vector2d& b, Opening& o)
{
	for (size_t i = 0; i < plan.walls.size(); i++)
	{
		const Wall& w = plan.walls[i];
		const Eigen::Vector2d d = (w.b - w.a).normalized(), n(-d[1], d[0]);
		const double len = (w.b - w.a).norm(), tol = 0.5 * w.thickness + 0.01;
		if (std::abs(n.dot(a - w.a)) > tol || std::abs(n.dot(b - w.a)) > tol) continue;
		double s0 = d.dot(a - w.a), s1 = d.dot(b - w.a);
		if (std::min(s0, s1) < -0.01 || std::max(s0, s1) > len + 0.01) continue;
		o.wall = i;
		o.s0 = std::clamp(std::min(s0, s1), 0.0, len), o.s1 = std::clamp(std::max(s0, s1), 0.0, len);
		o.hingeAtS0 = s0 <= s1;
		return;
	}
	p.fail("'" + p.item() + "' (" + std::to_string(a[0]) + ", " + std::to_string(a[1]) + ") -> (" +
		   std::to_string(b[0]) + ", " + std::to_string(b[1]) + ") is not on a wall (it must lie on a wall's centre line)");
}

void parseOpening(const LineParser& p, FloorPlan& plan)
{
	Opening o;
	Eigen::Vector2d a, b;
	if (p.item() == "doorway")
	{
		p.expectFields(5, 7, "X1 Y1 X2 Y2 HEIGHT [LEAF_TEXTURE [front|back]]");
		o.kind = Opening::Kind::Doorway;
		a = p.point(1), b = p.point(3);
		o.z0 = 0, o.z1 = p.positive(5, "height");
		if (p.size() >= 7) o.texture = p.texture(6), o.hasLeaf = true;
		if (p.size() == 8 && p.field(7) != "front" && p.field(7) != "back")
			p.fail("the leaf's side must be 'front' or 'back', got '" + p.field(7) + "'");
		o.leafToFront = p.size() < 8 || p.field(7) == "front";
	}
	else
	{
		p.expectFields(7, 7, "X1 Y1 X2 Y2 Z0 Z1 VIEW_TEXTURE");
		o.kind = Opening::Kind::Window;
		a = p.point(1), b = p.point(3);
		o.z0 = p.number(5, "z0"), o.z1 = p.number(6, "z1");
		if (o.z0 <= 0 || o.z1 <= o.z0) p.fail("window needs 0 < Z0 < Z1");
		o.texture = p.texture(7);
	}
	p.distinct(a, b);
	if (o.z1 > plan.ceilingHeight) p.fail("'" + p.item() + "' reaches above the ceiling");
	placeOpening(p, plan, a, b, o);
	o.line = p.line();
	plan.openings.push_back(o);
}

void parseFurniture(const LineParser& p, FloorPlan& plan)
{
	p.expectFields(4, 5, "X Y FACING NAME [ELEVATION]");
	Furniture f;
	f.centre = p.point(1);
	f.facing = p.number(3, "facing") * kDeg;
	f.item = findFurniture(p.field(4));
	if (!f.item) p.fail("unknown furniture '" + p.field(4) + "' (vslam-simul --list-furniture lists them)");
	f.elevation = p.size() == 6 ? p.number(5, "elevation") : f.item->elevation;
	if (f.elevation < 0) p.fail("elevation must not be negative");
	if (f.elevation + f.item->height > plan.ceilingHeight + 1e-6)
		p.fail("furniture '" + f.item->name + "' reaches above the ceiling");
	f.line = p.line();
	plan.furniture.push_back(f);
}

void parseWall(const LineParser& p, FloorPlan& plan)
{
	p.expectFields(6, 7, "X1 Y1 X2 Y2 THICKNESS FRONT_TEXTURE [BACK_TEXTURE]");
	if (!plan.openings.empty()) p.fail("walls must come before the doorways and windows");
	Wall w;
	w.a = p.point(1), w.b = p.point(3);
	p.distinct(w.a, w.b);
	w.thickness = p.positive(5, "thickness");
	w.front = p.texture(6);
	if (p.size() == 8) w.back = p.texture(7), w.hasBack = true;
	w.line = p.line();
	plan.walls.push_back(w);
}

void parseBox(const LineParser& p, FloorPlan& plan)
{
	p.expectFields(7, 7, "X Y YAW SIZE_X SIZE_Y HEIGHT TEXTURE");
	Box b;
	b.centre = p.point(1);
	b.yaw = p.number(3, "yaw") * kDeg;
	b.sizeX = p.positive(4, "size_x");
	b.sizeY = p.positive(5, "size_y");
	b.height = p.positive(6, "height");
	b.texture = p.texture(7);
	b.line = p.line();
	plan.boxes.push_back(b);
}

void parsePicture(const LineParser& p, FloorPlan& plan)
{
	p.expectFields(7, 7, "X1 Y1 X2 Y2 Z0 Z1 TEXTURE");
	Picture q;
	q.framed = p.item() == "picture";
	q.a = p.point(1), q.b = p.point(3);
	p.distinct(q.a, q.b);
	q.z0 = p.number(5, "z0"), q.z1 = p.number(6, "z1");
	if (q.z0 < 0 || q.z1 <= q.z0) p.fail("picture needs 0 <= Z0 < Z1");
	q.texture = p.texture(7);
	q.line = p.line();
	plan.pictures.push_back(q);
}

void parseDoor(const LineParser& p, FloorPlan& plan)
{
	p.expectFields(5, 5, "X1 Y1 X2 Y2 TEXTURE");
	Door d;
	d.a = p.point(1), d.b = p.point(3);
	p.distinct(d.a, d.b);
	d.texture = p.texture(5);
	d.line = p.line();
	plan.doors.push_back(d);
}

void parseItem(const LineParser& p, FloorPlan& plan)
{
	const std::string& item = p.item();
	if (item == "ceiling_height")
	{
		p.expectFields(1, 1, "H");
		plan.ceilingHeight = p.positive(1, "ceiling height");
		if (plan.ceilingHeight > 20) p.fail("ceiling height above 20 m");
	}
	else if (item == "material") parseMaterial(p, plan);
	else if (item == "floor") parseFloor(p, plan);
	else if (item == "ceiling")
	{
		p.expectFields(1, 1, "TEXTURE");
		plan.ceiling = p.texture(1), plan.hasCeilingTexture = true;
	}
	else if (item == "skirting")
	{
		p.expectFields(2, 2, "HEIGHT TEXTURE");
		plan.skirtingHeight = p.positive(1, "skirting height");
		if (plan.skirtingHeight > 0.5) p.fail("skirting above 0.5 m");
		plan.skirting = p.texture(2);
	}
	else if (item == "wall") parseWall(p, plan);
	else if (item == "doorway" || item == "window") parseOpening(p, plan);
	else if (item == "furniture") parseFurniture(p, plan);
	else if (item == "box") parseBox(p, plan);
	else if (item == "picture" || item == "panel") parsePicture(p, plan);
	else if (item == "door") parseDoor(p, plan);
	else
		p.fail("unknown item '" + item +
			   "' (expected ceiling_height, material, floor, ceiling, skirting, wall, doorway, window, furniture, "
			   "box, picture, panel or door)");
}
}  // namespace

FloorPlan parseFloorPlan(const std::string& text, const std::string& fileName, const std::string& textureDir)
{
	FloorPlan plan;
	plan.sourceFile = fileName;
	plan.textureDir = textureDir;
	AssetCache assets;
	std::istringstream in(text);
	std::string raw;
	int line = 0;
	while (std::getline(in, raw))
	{
		line++;
		if (raw.size() > 4096)
			throw InputError("world file '" + fileName + "' line " + std::to_string(line) + ": line too long");
		const auto hash = raw.find('#');
		if (hash != std::string::npos) raw.resize(hash);
		std::istringstream fs(raw);
		std::vector<std::string> fields;
		for (std::string f; fs >> f;) fields.push_back(f);
		if (fields.empty()) continue;
		parseItem(LineParser(fileName, line, std::move(fields), textureDir, plan, assets), plan);
	}
	if (plan.walls.empty()) throw InputError("world file '" + fileName + "': empty world (no wall)");
	checkWorldGeometry(plan);
	return plan;
}

FloorPlan loadFloorPlan(const std::string& file, const std::string& textureDir)
{
	std::ifstream in(file);
	if (!in) throw InputError("cannot read world file '" + file + "'");
	std::stringstream ss;
	ss << in.rdbuf();
	return parseFloorPlan(ss.str(), file, textureDir);
}
}  // namespace vslam::world
