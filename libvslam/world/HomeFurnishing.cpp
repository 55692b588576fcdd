#include <libvslam/world/FreeSpace.h>
#include <libvslam/world/HomeFurnishing.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace vslam::world
{
namespace
{
using Polygon = std::vector<Eigen::Vector2d>;

/** One side of a room's inner floor, counter-clockwise: the room is on
 * its left. */
struct Side
{
	Eigen::Vector2d p0, dir, inward;
	double length;
	Eigen::Vector2d at(double t) const { return p0 + t * dir; }
};

std::array<Side, 4> sidesOf(const HomeRoom& r)
{
	const Eigen::Vector2d lo = r.innerLo(), hi = r.innerHi();
	const double w = hi[0] - lo[0], h = hi[1] - lo[1];
	return {Side{{lo[0], lo[1]}, {1, 0}, {0, 1}, w}, Side{{hi[0], lo[1]}, {0, 1}, {-1, 0}, h},
		Side{{hi[0], hi[1]}, {-1, 0}, {0, -1}, w}, Side{{lo[0], hi[1]}, {0, -1}, {1, 0}, h}};
}

double angleOf(const Eigen::Vector2d& v) { return std::atan2(v[1], v[0]); }

Polygon rectangle(const Side& s, double t0, double t1, double depth)
{
	return {s.at(t0), s.at(t1), s.at(t1) + depth * s.inward, s.at(t0) + depth * s.inward};
}

/** An opening seen from one side of a room: where along it. */
struct SideOpening
{
	const Opening* opening;
	double t0, t1;
};

std::vector<SideOpening> openingsOn(const FloorPlan& plan, const Side& s)
{
	std::vector<SideOpening> out;
	for (const Opening& o : plan.openings)
	{
		const Wall& w = plan.walls[o.wall];
		const Eigen::Vector2d a = alongWall(w, o.s0), b = alongWall(w, o.s1);
		const Eigen::Vector2d n(-s.dir[1], s.dir[0]);
		if (std::abs(n.dot(a - s.p0)) > 0.15 || std::abs(n.dot(b - s.p0)) > 0.15) continue;
		double t0 = s.dir.dot(a - s.p0), t1 = s.dir.dot(b - s.p0);
		if (t0 > t1) std::swap(t0, t1);
		if (t1 < 0 || t0 > s.length) continue;
		out.push_back({&o, t0, t1});
	}
	return out;
}

/** Both sides of every doorway, where the robot passes. */
std::vector<Eigen::Vector2d> doorwayProbes(const FloorPlan& plan)
{
	std::vector<Eigen::Vector2d> out;
	for (const Opening& o : plan.openings)
	{
		if (o.kind != Opening::Kind::Doorway) continue;
		const Wall& w = plan.walls[o.wall];
		const Eigen::Vector2d mid = alongWall(w, 0.5 * (o.s0 + o.s1)), d = (w.b - w.a).normalized(), n(-d[1], d[0]);
		for (const double side : {1.0, -1.0}) out.push_back(mid + side * (0.5 * w.thickness + 0.45) * n);
	}
	return out;
}

/** Every probe reachable from the start, for a robot a little wider than
 * the simulated one (on a coarse grid: this runs for every item). */
bool reachable(const FloorPlan& plan, const std::vector<Eigen::Vector2d>& probes, const Eigen::Vector2d& start)
{
	try
	{
		const FreeSpace free(plan, 0.25, start, 0.1);
		for (const auto& p : probes)
			if (!free.isFree(p)) return false;
		return true;
	}
	catch (const std::exception&)
	{
		return false;
	}
}

class RoomFurnisher
{
   public:
	RoomFurnisher(FloorPlan& plan, const HomeRoom& room, std::vector<Polygon>& keepOut,
		const std::vector<Eigen::Vector2d>& probes, const Eigen::Vector2d& start, SeededRandom& rng)
		: m_plan(plan), m_room(room), m_sides(sidesOf(room)), m_keepOut(keepOut), m_probes(probes), m_start(start),
		  m_rng(rng)
	{
		for (size_t k = 0; k < 4; k++) m_openings[k] = openingsOn(plan, m_sides[k]);
	}

	const Side& side(int k) const { return m_sides[static_cast<size_t>(k)]; }
	const std::vector<SideOpening>& openings(int k) const { return m_openings[static_cast<size_t>(k)]; }
	SeededRandom& rng() { return m_rng; }
	double ceiling() const { return m_plan.ceilingHeight; }

	/** `item` with its back against side k, centred t along it. */
	Furniture against(const FurnitureItem& item, int k, double t, double elevation = -1) const
	{
		const Side& s = side(k);
		Furniture f;
		f.item = &item;
		f.centre = s.at(t) + (0.5 * item.depth + 0.01) * s.inward;
		f.facing = angleOf(s.inward);
		f.elevation = elevation >= 0 ? elevation : item.elevation;
		return f;
	}

	/** Fits: on the room's floor, clear of other furniture and the
	 * doorways, not in front of a window if it is taller than the sill. */
	bool fits(const Furniture& f, int againstSide = -1) const
	{
		const Polygon fp = footprint(f);
		const Eigen::Vector2d lo = m_room.innerLo(), hi = m_room.innerHi();
		for (const auto& p : fp)
			if (p[0] < lo[0] - 1e-6 || p[1] < lo[1] - 1e-6 || p[0] > hi[0] + 1e-6 || p[1] > hi[1] + 1e-6) return false;
		const double top = f.elevation + f.item->height, bottom = f.elevation;
		for (const Furniture& g : m_plan.furniture)
		{
			const bool stacked = bottom >= g.elevation + g.item->height - 1e-6 || top <= g.elevation + 1e-6;
			if (!stacked && convexOverlap(fp, footprint(g), 0.02)) return false;
		}
		if (f.item->isObstacle())
			for (const Polygon& k : m_keepOut)
				if (convexOverlap(fp, k, 0)) return false;
		if (againstSide >= 0)
		{
			const Side& s = side(againstSide);
			const double half = 0.5 * f.item->width, t = s.dir.dot(f.centre - s.p0);
			for (const SideOpening& o : openings(againstSide))
				if (o.opening->kind == Opening::Kind::Window && t + half > o.t0 - 0.1 && t - half < o.t1 + 0.1 &&
					top > o.opening->z0 - 0.03 && bottom < o.opening->z1)
					return false;
		}
		return true;
	}

	/** Adds it if it fits and every doorway stays reachable. */
	bool add(const Furniture& f, int againstSide = -1)
	{
		if (!fits(f, againstSide)) return false;
		m_plan.furniture.push_back(f);
		if (f.item->isObstacle() && !doorwaysReachable())
		{
			m_plan.furniture.pop_back();
			return false;
		}
		return true;
	}

	/** `item` against some side (preferred ones first), anywhere along it. */
	std::optional<Furniture> placeAgainstWall(const FurnitureItem& item, std::vector<int> sides = {0, 1, 2, 3})
	{
		for (int attempt = 0; attempt < 40; attempt++)
		{
			const int k = sides[static_cast<size_t>(attempt) % sides.size()];
			const double free = side(k).length - item.width;
			if (free < 0) continue;
			const Furniture f = against(item, k, 0.5 * item.width + m_rng.uniform(0, free));
			if (add(f, k)) return f;
		}
		return std::nullopt;
	}

	/** Sides in a random order, the longest without a doorway first. */
	std::vector<int> sidesByRoom()
	{
		std::vector<int> order{0, 1, 2, 3};
		std::vector<double> score(4);
		for (int k = 0; k < 4; k++)
		{
			bool door = false;
			for (const SideOpening& o : openings(k)) door = door || o.opening->kind == Opening::Kind::Doorway;
			score[static_cast<size_t>(k)] = side(k).length - (door ? 3.0 : 0.0) + m_rng.uniform(0, 1.0);
		}
		std::sort(order.begin(), order.end(), [&](int a, int b) { return score[static_cast<size_t>(a)] > score[static_cast<size_t>(b)]; });
		return order;
	}

   private:
	FloorPlan& m_plan;
	const HomeRoom& m_room;
	std::array<Side, 4> m_sides;
	std::array<std::vector<SideOpening>, 4> m_openings;
	std::vector<Polygon>& m_keepOut;
	const std::vector<Eigen::Vector2d>& m_probes;
	Eigen::Vector2d m_start;
	SeededRandom& m_rng;

	bool doorwaysReachable() const { return reachable(m_plan, m_probes, m_start); }
};

const FurnitureItem& pick(FurnitureRole role, SeededRandom& rng) { return *rng.pick(furnitureOfRole(role)); }

/** Radiators centred under every window, the lamp on the ceiling. */
void addFittings(RoomFurnisher& r, const HomeStyle& style, const HomeRoom& room)
{
	for (int k = 0; k < 4; k++)
		for (const SideOpening& o : r.openings(k))
			if (o.opening->kind == Opening::Kind::Window)
				r.add(r.against(*style.radiator, k, 0.5 * (o.t0 + o.t1)), k);
	const FurnitureItem& lamp = *findFurniture("ceiling_lamp");
	Furniture f;
	f.item = &lamp;
	f.centre = 0.5 * (room.innerLo() + room.innerHi());
	f.elevation = r.ceiling() - lamp.height;
	r.add(f);
}

/** A table with chairs on its long sides, standing free where there is room. */
void addDiningTable(RoomFurnisher& r, const HomeRoom& room, FurnitureRole tableRole)
{
	SeededRandom& rng = r.rng();
	const FurnitureItem& table = pick(tableRole, rng);
	const FurnitureItem& chair = pick(FurnitureRole::Chair, rng);
	const Eigen::Vector2d lo = room.innerLo(), hi = room.innerHi();
	for (int attempt = 0; attempt < 30; attempt++)
	{
		Furniture t;
		t.item = &table;
		t.facing = rng.chance(0.5) ? 0 : M_PI / 2;
		t.centre = {rng.uniform(lo[0] + 1.2, std::max(lo[0] + 1.2, hi[0] - 1.2)), rng.uniform(lo[1] + 1.2, std::max(lo[1] + 1.2, hi[1] - 1.2))};
		if (!r.fits(t)) continue;
		// Keep a chair's depth free around it before committing.
		Furniture inflated = t;
		FurnitureItem big = table;
		big.width += 0.9, big.depth += 1.1;
		inflated.item = &big;
		if (!r.fits(inflated) || !r.add(t)) continue;
		const Eigen::Vector2d across(std::cos(t.facing), std::sin(t.facing)), along(-across[1], across[0]);
		const int perSide = table.width > 1.3 ? 2 : 1;
		for (const double s : {1.0, -1.0})
			for (int c = 0; c < perSide; c++)
			{
				Furniture ch;
				ch.item = &chair;
				const double offset = perSide == 1 ? 0 : (c - 0.5) * table.width * 0.5;
				ch.centre = t.centre + s * (0.5 * table.depth + 0.5 * chair.depth + 0.02) * across + offset * along;
				ch.facing = angleOf(-s * across);  // towards the table
				r.add(ch);
			}
		const FurnitureItem& pendant = *findFurniture("pendant_lamp");
		Furniture lamp;
		lamp.item = &pendant;
		lamp.centre = t.centre;
		lamp.elevation = r.ceiling() - pendant.height;
		r.add(lamp);
		return;
	}
}

void furnishLiving(RoomFurnisher& r, const HomeRoom& room)
{
	SeededRandom& rng = r.rng();
	const auto sides = r.sidesByRoom();
	const std::optional<Furniture> sofa = r.placeAgainstWall(pick(FurnitureRole::Sofa, rng), {sides[0], sides[1]});
	if (sofa)
	{
		// The coffee table in front of it, the TV across the room facing it.
		const FurnitureItem& table = pick(FurnitureRole::CoffeeTable, rng);
		const Eigen::Vector2d ahead(std::cos(sofa->facing), std::sin(sofa->facing));
		Furniture t{&table, sofa->centre + (0.5 * sofa->item->depth + 0.45 + 0.5 * table.depth) * ahead, sofa->facing, 0, 0};
		r.add(t);
		for (int k = 0; k < 4; k++)
		{
			const Side& s = r.side(k);
			if (s.inward.dot(ahead) > -0.99) continue;
			const FurnitureItem& stand = *findFurniture("tv_stand");
			const Furniture st = r.against(stand, k, std::clamp(s.dir.dot(sofa->centre - s.p0), 0.7, s.length - 0.7));
			if (r.add(st, k)) r.add(Furniture{findFurniture("tv_flat"), st.centre, st.facing, stand.height, 0});
		}
		if (rng.chance(0.7))
		{
			const FurnitureItem& chair = pick(FurnitureRole::Armchair, rng);
			const Eigen::Vector2d side(-ahead[1], ahead[0]);
			const double s = rng.chance(0.5) ? 1 : -1;
			r.add(Furniture{&chair, t.centre + s * (0.5 * table.width + 0.55) * side, angleOf(-s * side), 0, 0});
		}
	}
	for (int i = rng.integer(1, 2); i > 0; i--) r.placeAgainstWall(pick(FurnitureRole::Bookcase, rng), {sides[1], sides[2], sides[3]});
	for (int i = rng.integer(1, 2); i > 0; i--) r.placeAgainstWall(pick(FurnitureRole::Plant, rng));
	if (rng.chance(0.5)) r.placeAgainstWall(*findFurniture("floor_lamp"));
	if (rng.chance(0.5)) r.placeAgainstWall(*findFurniture(rng.chance(0.5) ? "dresser" : "shelves_low"));
	if (rng.chance(0.15)) r.placeAgainstWall(*findFurniture("fireplace"));
	if (rng.chance(0.12)) r.placeAgainstWall(*findFurniture("piano_upright"));
	const Eigen::Vector2d size = room.innerHi() - room.innerLo();
	if (room.kind == RoomKind::LivingKitchen || size[0] * size[1] > 22) addDiningTable(r, room, FurnitureRole::DiningTable);
}

/** A run of kitchen units along one wall, wall cabinets above, tiles
 * between them. */
void addKitchenRun(FloorPlan& plan, RoomFurnisher& r, const HomeStyle& style)
{
	SeededRandom& rng = r.rng();
	const int k = r.sidesByRoom()[0];
	const Side& s = r.side(k);
	std::vector<const FurnitureItem*> units{findFurniture(rng.chance(0.5) ? "fridge" : "kitchen_tall")};
	const int lowers = std::max(2, static_cast<int>((s.length - 1.9) / 0.6));
	for (int i = 0; i < lowers; i++)
		units.push_back(findFurniture(i == 1 ? "kitchen_sink" : (i % 3 == 2 ? "kitchen_drawers" : "kitchen_lower")));
	if (rng.chance(0.6) && lowers > 3) units.insert(units.begin() + 3, findFurniture("kitchen_stove"));
	if (rng.chance(0.5)) std::reverse(units.begin(), units.end());
	double t = 0.02, counterFrom = -1, counterTo = -1;
	for (const FurnitureItem* u : units)
	{
		if (t + u->width > s.length) break;
		const bool counter = u->role != FurnitureRole::KitchenTall;
		if (r.add(r.against(*u, k, t + 0.5 * u->width), k) && counter)
		{
			if (counterFrom < 0) counterFrom = t;
			counterTo = t + u->width;
			if (u->role != FurnitureRole::KitchenStove && u->width < 0.7)
				r.add(r.against(*findFurniture("kitchen_upper"), k, t + 0.5 * u->width), k);
		}
		t += u->width + 0.005;
	}
	if (counterTo > counterFrom + 0.5)
		plan.pictures.push_back({s.at(counterFrom), s.at(counterTo), 0.9, 1.45, materialRef(style.wallTiles), 0, false});
}

void furnishBedroom(RoomFurnisher& r)
{
	SeededRandom& rng = r.rng();
	const auto sides = r.sidesByRoom();
	const FurnitureItem& bed = pick(FurnitureRole::Bed, rng);
	if (const auto b = r.placeAgainstWall(bed, {sides[0], sides[1]}))
		for (int k = 0; k < 4; k++)
		{
			const Side& s = r.side(k);
			if (std::abs(angleOf(s.inward) - b->facing) > 1e-6) continue;
			const double t = s.dir.dot(b->centre - s.p0);
			const FurnitureItem& table = pick(FurnitureRole::BedsideTable, rng);
			for (const double side : {1.0, -1.0})
				r.add(r.against(table, k, t + side * (0.5 * bed.width + 0.5 * table.width + 0.03)), k);
		}
	r.placeAgainstWall(pick(FurnitureRole::Wardrobe, rng), {sides[1], sides[2], sides[3], sides[0]});
	if (rng.chance(0.5)) r.placeAgainstWall(*findFurniture("dresser"));
	if (rng.chance(0.4)) r.placeAgainstWall(pick(FurnitureRole::Bookcase, rng));
	if (rng.chance(0.5)) r.placeAgainstWall(pick(FurnitureRole::Plant, rng));
}

void furnishStudy(RoomFurnisher& r)
{
	SeededRandom& rng = r.rng();
	if (const auto desk = r.placeAgainstWall(pick(FurnitureRole::Desk, rng), r.sidesByRoom()))
	{
		const Eigen::Vector2d ahead(std::cos(desk->facing), std::sin(desk->facing));
		const FurnitureItem& chair = *findFurniture("desk_chair");
		r.add(Furniture{&chair, desk->centre + (0.5 * desk->item->depth + 0.5 * chair.depth + 0.05) * ahead, desk->facing + M_PI, 0, 0});
	}
	for (int i = rng.integer(1, 2); i > 0; i--) r.placeAgainstWall(pick(FurnitureRole::Bookcase, rng));
	if (rng.chance(0.6)) r.placeAgainstWall(pick(FurnitureRole::Armchair, rng));
	r.placeAgainstWall(pick(FurnitureRole::Plant, rng));
}

void furnishHall(RoomFurnisher& r, const HomeRoom& room)
{
	SeededRandom& rng = r.rng();
	const Eigen::Vector2d size = room.innerHi() - room.innerLo();
	// The front door at one end, closed; cupboard, bathroom and toilet doors
	// along the sides, all alike.
	const bool alongX = size[0] > size[1];
	const int end = alongX ? (rng.chance(0.5) ? 1 : 3) : (rng.chance(0.5) ? 0 : 2);
	const FurnitureItem& door = *findFurniture(rng.chance(0.5) ? "door_wood" : "door_white");
	r.add(r.against(door, end, 0.5 * r.side(end).length), end);
	const std::vector<int> sides = alongX ? std::vector<int>{0, 2} : std::vector<int>{1, 3};
	for (int n = rng.integer(1, 3); n > 0; n--) r.placeAgainstWall(door, sides);
	if (std::min(size[0], size[1]) > 1.3 && rng.chance(0.6))
		r.placeAgainstWall(*findFurniture(rng.chance(0.5) ? "dresser" : "bookcase_low"), sides);
	if (rng.chance(0.5)) r.placeAgainstWall(pick(FurnitureRole::Plant, rng));
}

/** Things standing on the furniture a room has from `firstItem` on: a lamp
 * on a bedside table, a vase on a sideboard, a microwave on the counter. */
void addDecor(FloorPlan& plan, RoomFurnisher& r, size_t firstItem)
{
	SeededRandom& rng = r.rng();
	const size_t end = plan.furniture.size();
	for (size_t i = firstItem; i < end; i++)
	{
		const Furniture host = plan.furniture[i];
		const FurnitureRole role = host.item->role;
		const bool kitchen = role == FurnitureRole::KitchenLower;
		const bool surface = kitchen || role == FurnitureRole::CoffeeTable || role == FurnitureRole::BedsideTable ||
			role == FurnitureRole::Dresser || role == FurnitureRole::Desk || role == FurnitureRole::DiningTable ||
			role == FurnitureRole::Piano || role == FurnitureRole::Fireplace ||
			(role == FurnitureRole::Bookcase && host.item->height < 1.6) || (role == FurnitureRole::TvStand && host.item->height < 1);
		if (!surface || !rng.chance(kitchen ? 0.35 : 0.8)) continue;
		const Eigen::Vector2d ahead(std::cos(host.facing), std::sin(host.facing)), across(-ahead[1], ahead[0]);
		for (int n = rng.integer(1, kitchen ? 1 : 3); n > 0; n--)
			for (int attempt = 0; attempt < 8; attempt++)
			{
				const FurnitureItem& item = pick(kitchen ? FurnitureRole::KitchenDecor : FurnitureRole::Decor, rng);
				const double freeW = host.item->width - item.width - 0.04, freeD = host.item->depth - item.depth - 0.04;
				if (freeW < 0 || freeD < 0) continue;
				Furniture f{&item, host.centre + rng.uniform(-0.5, 0.5) * freeW * across + rng.uniform(-0.5, 0.5) * freeD * ahead,
					host.facing, host.elevation + host.item->height, 0};
				if (f.elevation + item.height < r.ceiling() - 0.1 && r.add(f)) break;
			}
	}
}

/** A light switch beside each doorway, on the room's side. */
void addSwitches(RoomFurnisher& r)
{
	const FurnitureItem& sw = *findFurniture(r.rng().chance(0.5) ? "switch_square" : "switch_double");
	for (int k = 0; k < 4; k++)
		for (const SideOpening& o : r.openings(k))
			if (o.opening->kind == Opening::Kind::Doorway)
			{
				const double t = r.rng().chance(0.5) ? o.t1 + 0.18 : o.t0 - 0.18;
				if (t > 0.1 && t < r.side(k).length - 0.1) r.add(r.against(sw, k, t), k);
			}
}

/** A few things on the floor, a clock on a wall. */
void addClutter(RoomFurnisher& r, RoomKind kind)
{
	SeededRandom& rng = r.rng();
	if (kind == RoomKind::Hall || kind == RoomKind::Kitchen) return;
	for (int n = rng.integer(0, 2); n > 0; n--) r.placeAgainstWall(pick(FurnitureRole::Clutter, rng));
	if (kind != RoomKind::Bedroom && rng.chance(0.3)) r.placeAgainstWall(pick(FurnitureRole::WallDecor, rng));
}

/** Free stretches of side k for a picture: no opening, no tall furniture
 * against it; the height below that low furniture takes. */
struct WallSpan
{
	double t0, t1, above;
};

std::vector<WallSpan> pictureSpans(const FloorPlan& plan, const RoomFurnisher& r, int k)
{
	const Side& s = r.side(k);
	std::vector<std::pair<double, double>> blocked;
	for (const SideOpening& o : r.openings(k)) blocked.emplace_back(o.t0 - 0.2, o.t1 + 0.2);
	std::vector<std::pair<std::pair<double, double>, double>> low;
	for (const Furniture& f : plan.furniture)
	{
		const Eigen::Vector2d back = f.centre - s.p0;
		if (std::abs(s.inward.dot(back) - 0.5 * f.item->depth) > 0.1 || std::abs(angleOf(s.inward) - f.facing) > 1e-6) continue;
		const double t = s.dir.dot(back), half = 0.5 * f.item->width + 0.05, top = f.elevation + f.item->height;
		if (top > 1.05) blocked.emplace_back(t - half, t + half);
		else low.push_back({{t - half, t + half}, top});
	}
	blocked.emplace_back(-1, 0.15);
	blocked.emplace_back(s.length - 0.15, s.length + 1);
	std::sort(blocked.begin(), blocked.end());
	std::vector<WallSpan> spans;
	double from = 0;
	for (const auto& [b0, b1] : blocked)
	{
		if (b0 - from > 0.45)
		{
			double above = 0;
			for (const auto& [range, top] : low)
				if (range.second > from && range.first < b0) above = std::max(above, top);
			spans.push_back({from, b0, above});
		}
		from = std::max(from, b1);
	}
	return spans;
}

bool hangPicture(FloorPlan& plan, const RoomFurnisher& r, const TextureRef& texture, SeededRandom& rng)
{
	const int k = rng.integer(0, 3);
	const auto spans = pictureSpans(plan, r, k);
	if (spans.empty()) return false;
	const WallSpan& span = rng.pick(spans);
	const double aspect = rng.pick(std::vector<double>{0.7, 1.0, 1.4, 1.6});
	const double w = std::min(span.t1 - span.t0 - 0.1, rng.uniform(0.4, 1.3)), h = w / aspect;
	const double z0 = std::max(span.above + 0.3, rng.uniform(1.15, 1.45)), z1 = z0 + h;
	if (w < 0.3 || z1 > plan.ceilingHeight - 0.25) return false;
	const double t0 = span.t0 + rng.uniform(0.05, span.t1 - span.t0 - w - 0.05 + 1e-9);
	const Side& s = r.side(k);
	for (const Picture& q : plan.pictures)  // not over another picture
	{
		const double q0 = s.dir.dot(q.a - s.p0), q1 = s.dir.dot(q.b - s.p0);
		if (std::abs(s.inward.dot(q.a - s.p0)) < 0.05 && std::max(q0, q1) > t0 - 0.1 && std::min(q0, q1) < t0 + w + 0.1 &&
			q.z1 > z0 - 0.1 && q.z0 < z1 + 0.1)
			return false;
	}
	plan.pictures.push_back({s.at(t0), s.at(t0 + w), z0, z1, texture, 0});
	return true;
}

/** Pictures, room after room, until they cover the home's share of the
 * wall area (6-11%: a minority, as in lived-in homes); one of them hangs in
 * two rooms. */
void decorate(FloorPlan& plan, const std::vector<RoomFurnisher*>& rooms, const std::vector<RoomKind>& kinds,
	const HomeStyle& style, SeededRandom& rng)
{
	const double share = rng.uniform(0.06, 0.11);
	const TextureRef twice = rng.pick(style.pictures);
	int hungTwice = 0;
	for (int round = 0; round < 12 && plan.decoratedWallShare() < share; round++)
		for (size_t i = 0; i < rooms.size() && plan.decoratedWallShare() < share; i++)
		{
			if (kinds[i] == RoomKind::Kitchen && round > 1) continue;  // kitchens: a calendar or two
			const bool repeat = hungTwice < 2 && round == 0 && rng.chance(0.5);
			const TextureRef& t = repeat ? twice : rng.pick(style.pictures);
			for (int attempt = 0; attempt < 10; attempt++)
				if (hangPicture(plan, *rooms[i], t, rng))
				{
					hungTwice += repeat;
					break;
				}
		}
}
}  // namespace

void furnishHome(FloorPlan& plan, const HomeLayout& layout, const HomeStyle& style, const Eigen::Vector2d& start,
	SeededRandom& rng)
{
	// Doorways and the start stay clear of furniture.
	std::vector<Polygon> keepOut{{start + Eigen::Vector2d(-0.6, -0.6), start + Eigen::Vector2d(0.6, -0.6),
		start + Eigen::Vector2d(0.6, 0.6), start + Eigen::Vector2d(-0.6, 0.6)}};
	for (const HomeRoom& room : layout.rooms)
		for (const Side& s : sidesOf(room))
			for (const SideOpening& o : openingsOn(plan, s))
				if (o.opening->kind == Opening::Kind::Doorway)
					keepOut.push_back(rectangle(s, o.t0 - 0.3, o.t1 + 0.3, o.t1 - o.t0 + 0.4));
	// The doorways' sides the bare home lets the robot reach must stay reachable.
	std::vector<Eigen::Vector2d> probes;
	for (const auto& p : doorwayProbes(plan))
		if (reachable(plan, {p}, start)) probes.push_back(p);
	std::vector<std::unique_ptr<RoomFurnisher>> furnishers;
	std::vector<RoomFurnisher*> rooms;
	std::vector<RoomKind> kinds;
	for (const HomeRoom& room : layout.rooms)
	{
		furnishers.push_back(std::make_unique<RoomFurnisher>(plan, room, keepOut, probes, start, rng));
		RoomFurnisher& r = *furnishers.back();
		const size_t first = plan.furniture.size();
		addFittings(r, style, room);
		addSwitches(r);
		switch (room.kind)
		{
			case RoomKind::Living: furnishLiving(r, room); break;
			case RoomKind::LivingKitchen: addKitchenRun(plan, r, style); furnishLiving(r, room); break;
			case RoomKind::Kitchen:
				addKitchenRun(plan, r, style);
				addDiningTable(r, room, FurnitureRole::DiningTable);
				break;
			case RoomKind::Bedroom: furnishBedroom(r); break;
			case RoomKind::Study: furnishStudy(r); break;
			case RoomKind::Hall: furnishHall(r, room); break;
		}
		addClutter(r, room.kind);
		addDecor(plan, r, first);
		rooms.push_back(&r);
		kinds.push_back(room.kind);
	}
	decorate(plan, rooms, kinds, style, rng);
}
}  // namespace vslam::world
