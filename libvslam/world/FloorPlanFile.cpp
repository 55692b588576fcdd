#include <libvslam/core/InputError.h>
#include <libvslam/world/FloorPlanFile.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace vslam::world
{
namespace
{
class LineParser
{
   public:
	LineParser(const std::string& file, int line, std::vector<std::string> fields, const std::string& textureDir)
		: m_file(file), m_line(line), m_fields(std::move(fields)), m_textureDir(textureDir)
	{
	}

	[[noreturn]] void fail(const std::string& what) const
	{
		throw InputError("world file '" + m_file + "' line " + std::to_string(m_line) + ": " + what);
	}

	const std::string& item() const { return m_fields[0]; }

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

	TextureRef texture(size_t i) const
	{
		std::string spec = m_fields.at(i);
		TextureRef t;
		if (!spec.empty() && spec.back() == '~') t.mirrored = true, spec.pop_back();
		const auto at = spec.find('@');
		if (at != std::string::npos)
		{
			std::vector<double> f;
			std::stringstream ss(spec.substr(at + 1));
			std::string part;
			while (std::getline(ss, part, ','))
			{
				size_t used = 0;
				double v = -1;
				try
				{
					v = std::stod(part, &used);
				}
				catch (const std::exception&)
				{
					used = 0;
				}
				if (used != part.size() || !(v >= 0 && v <= 1))
					fail("bad texture part '" + spec.substr(at) + "' (expected @U0,V0,U1,V1 in [0, 1])");
				f.push_back(v);
			}
			if (f.size() != 4 || f[2] <= f[0] || f[3] <= f[1])
				fail("bad texture part '" + spec.substr(at) + "' (expected @U0,V0,U1,V1 with U0<U1, V0<V1)");
			t.u0 = f[0], t.v0 = f[1], t.u1 = f[2], t.v1 = f[3];
			spec.resize(at);
		}
		const std::filesystem::path p =
			std::filesystem::path(spec).is_absolute() ? std::filesystem::path(spec)
													   : std::filesystem::path(m_textureDir) / spec;
		std::error_code ec;
		if (spec.empty() || !std::filesystem::is_regular_file(p, ec))
			fail("unknown texture '" + spec + "' (no file " + p.string() + ")");
		t.file = p.string();
		return t;
	}

	void distinct(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const
	{
		if ((b - a).norm() < 1e-3) fail("'" + item() + "' has zero length");
	}

	size_t size() const { return m_fields.size(); }

   private:
	std::string m_file;
	int m_line;
	std::vector<std::string> m_fields;
	std::string m_textureDir;
};

void parseItem(const LineParser& p, FloorPlan& plan, int line)
{
	const std::string& item = p.item();
	if (item == "ceiling_height")
	{
		p.expectFields(1, 1, "H");
		plan.ceilingHeight = p.positive(1, "ceiling height");
		if (plan.ceilingHeight > 20) p.fail("ceiling height above 20 m");
	}
	else if (item == "floor")
	{
		p.expectFields(1, 1, "TEXTURE");
		plan.floor = p.texture(1);
		plan.hasFloorTexture = true;
	}
	else if (item == "wall")
	{
		p.expectFields(6, 7, "X1 Y1 X2 Y2 THICKNESS FRONT_TEXTURE [BACK_TEXTURE]");
		Wall w;
		w.a = p.point(1), w.b = p.point(3);
		p.distinct(w.a, w.b);
		w.thickness = p.positive(5, "thickness");
		w.front = p.texture(6);
		if (p.size() == 8) w.back = p.texture(7), w.hasBack = true;
		w.line = line;
		plan.walls.push_back(w);
	}
	else if (item == "box")
	{
		p.expectFields(7, 7, "X Y YAW SIZE_X SIZE_Y HEIGHT TEXTURE");
		Box b;
		b.centre = p.point(1);
		b.yaw = p.number(3, "yaw") * M_PI / 180;
		b.sizeX = p.positive(4, "size_x");
		b.sizeY = p.positive(5, "size_y");
		b.height = p.positive(6, "height");
		b.texture = p.texture(7);
		b.line = line;
		plan.boxes.push_back(b);
	}
	else if (item == "picture")
	{
		p.expectFields(7, 7, "X1 Y1 X2 Y2 Z0 Z1 TEXTURE");
		Picture q;
		q.a = p.point(1), q.b = p.point(3);
		p.distinct(q.a, q.b);
		q.z0 = p.number(5, "z0"), q.z1 = p.number(6, "z1");
		if (q.z0 < 0 || q.z1 <= q.z0) p.fail("picture needs 0 <= Z0 < Z1");
		q.texture = p.texture(7);
		q.line = line;
		plan.pictures.push_back(q);
	}
	else if (item == "door")
	{
		p.expectFields(5, 5, "X1 Y1 X2 Y2 TEXTURE");
		Door d;
		d.a = p.point(1), d.b = p.point(3);
		p.distinct(d.a, d.b);
		d.texture = p.texture(5);
		d.line = line;
		plan.doors.push_back(d);
	}
	else
		p.fail("unknown item '" + item +
			   "' (expected ceiling_height, floor, wall, box, picture or door)");
}
}  // namespace

FloorPlan parseFloorPlan(const std::string& text, const std::string& fileName, const std::string& textureDir)
{
	FloorPlan plan;
	plan.sourceFile = fileName;
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
		parseItem(LineParser(fileName, line, std::move(fields), textureDir), plan, line);
	}
	if (plan.walls.empty())
		throw InputError("world file '" + fileName + "': empty world (no wall)");
	for (const Picture& q : plan.pictures)
		if (q.z1 > plan.ceilingHeight)
			throw InputError(
				"world file '" + fileName + "' line " + std::to_string(q.line) +
				": picture reaches above the ceiling");
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
