#include <libvslam/world/FreeSpace.h>
#include <libvslam/world/HomeLayout.h>

#include <algorithm>
#include <cmath>

namespace vslam::world
{
namespace
{
/** Cuts [0, length] into n parts each at least `minPart` long. */
std::vector<double> cuts(double length, int n, double minPart, SeededRandom& rng)
{
	std::vector<double> at{0};
	double left = length;
	for (int i = n; i > 1; i--)
	{
		const double hi = left - minPart * (i - 1), lo = minPart;
		const double even = left / i, part = std::clamp(even * rng.uniform(0.75, 1.25), lo, std::max(lo, hi));
		at.push_back(at.back() + part);
		left -= part;
	}
	at.push_back(length);
	return at;
}

/** A strip [x0, x1] x [y0, y1] cut along x into rooms of `kinds`. */
void stripRooms(std::vector<HomeRoom>& rooms, double x0, double x1, double y0, double y1, const std::vector<RoomKind>& kinds,
	SeededRandom& rng)
{
	const auto at = cuts(x1 - x0, static_cast<int>(kinds.size()), 2.5, rng);
	for (size_t i = 0; i < kinds.size(); i++) rooms.push_back({kinds[i], {x0 + at[i], y0}, {x0 + at[i + 1], y1}});
}

/** Rooms per strip for its length: 2.5-8 m each, about 4 m. */
int roomsFor(double length, SeededRandom& rng)
{
	return std::clamp(static_cast<int>(std::round(length / rng.uniform(3.5, 5.0))), static_cast<int>(std::ceil(length / 8)),
		static_cast<int>(std::floor(length / 2.5)));
}

std::vector<RoomKind> privateRooms(int n, SeededRandom& rng)
{
	std::vector<RoomKind> kinds;
	for (int i = 0; i < n; i++) kinds.push_back(rng.chance(0.3) ? RoomKind::Study : RoomKind::Bedroom);
	return kinds;
}

HomeLayout hallwayHome(SeededRandom& rng, Eigen::Vector2d& size)
{
	const double w = rng.uniform(8.5, 14), hall = rng.uniform(1.1, 1.5);
	const double south = rng.uniform(3.2, 5.0), north = rng.uniform(2.8, 4.2);
	size = {w, south + hall + north};
	HomeLayout h;
	// The south side has the living room and the kitchen, the north side the private rooms.
	const int ns = std::max(2, roomsFor(w, rng)), nn = roomsFor(w, rng);
	std::vector<RoomKind> southKinds = privateRooms(ns, rng);
	southKinds[0] = RoomKind::Living;
	southKinds[static_cast<size_t>(ns - 1)] = RoomKind::Kitchen;
	stripRooms(h.rooms, 0, w, 0, south, southKinds, rng);
	stripRooms(h.rooms, 0, w, south + hall, size[1], privateRooms(nn, rng), rng);
	h.hub = h.rooms.size();
	h.rooms.push_back({RoomKind::Hall, {0, south}, {w, south + hall}});
	return h;
}

HomeLayout openPlanHome(SeededRandom& rng, Eigen::Vector2d& size)
{
	const double w = rng.uniform(6.5, 9.5), open = rng.uniform(3.8, 5.5), rooms = rng.uniform(2.8, 4.2);
	size = {w, open + rooms};
	HomeLayout h;
	h.rooms.push_back({RoomKind::LivingKitchen, {0, 0}, {w, open}});
	stripRooms(h.rooms, 0, w, open, size[1], privateRooms(std::max(2, roomsFor(w, rng)), rng), rng);
	h.hub = 0;
	return h;
}

struct SideLine
{
	bool horizontal;
	double at, from, to;  //!< the line's coordinate and its extent along it
};

/** Side k (south, east, north, west) of a room. */
SideLine side(const HomeRoom& r, int k)
{
	switch (k)
	{
		case 0: return {true, r.lo[1], r.lo[0], r.hi[0]};
		case 1: return {false, r.hi[0], r.lo[1], r.hi[1]};
		case 2: return {true, r.hi[1], r.lo[0], r.hi[0]};
		default: return {false, r.lo[0], r.lo[1], r.hi[1]};
	}
}

/** The wall along side k from s0 to s1 (coordinates along the side),
 * running so that its front faces into the room. */
std::pair<Eigen::Vector2d, Eigen::Vector2d> wallEnds(int k, const SideLine& l, double s0, double s1)
{
	const auto p = [&](double s) { return l.horizontal ? Eigen::Vector2d(s, l.at) : Eigen::Vector2d(l.at, s); };
	return (k == 0 || k == 1) ? std::make_pair(p(s0), p(s1)) : std::make_pair(p(s1), p(s0));
}

/** What the face of room r's side k shows. */
TextureRef faceOf(const HomeRoom& r, int k, const HomeStyle& style)
{
	return materialRef(k == r.featureWall ? style.wallpaper : r.paint);
}

/** Walls of every room side: inner walls once (front to the room listed
 * first), outer walls where no room is beyond. Returns, per room pair, the
 * walls between them. */
std::vector<std::vector<std::vector<size_t>>> buildWalls(FloorPlan& plan, HomeLayout& h, const HomeStyle& style)
{
	const size_t n = h.rooms.size();
	std::vector<std::vector<std::vector<size_t>>> between(n, std::vector<std::vector<size_t>>(n));
	for (size_t i = 0; i < n; i++)
		for (int k = 0; k < 4; k++)
		{
			const SideLine l = side(h.rooms[i], k);
			std::vector<std::pair<double, double>> covered;
			for (size_t j = 0; j < n; j++)
			{
				if (j == i) continue;
				const SideLine m = side(h.rooms[j], (k + 2) % 4);
				if (std::abs(m.at - l.at) > 1e-9) continue;
				const double s0 = std::max(l.from, m.from), s1 = std::min(l.to, m.to);
				if (s1 - s0 < 1e-6) continue;
				covered.emplace_back(s0, s1);
				if (j < i) continue;  // made from room j's side
				const auto [a, b] = wallEnds(k, l, s0, s1);
				plan.walls.push_back({a, b, 2 * kInnerHalf, faceOf(h.rooms[i], k, style), true, faceOf(h.rooms[j], (k + 2) % 4, style), 0});
				between[i][j].push_back(plan.walls.size() - 1);
				between[j][i].push_back(plan.walls.size() - 1);
			}
			std::sort(covered.begin(), covered.end());
			double s = l.from;
			covered.emplace_back(l.to, l.to);
			for (const auto& [c0, c1] : covered)
			{
				if (c0 - s > 1e-6)
				{
					const auto [a, b] = wallEnds(k, l, s, c0);
					plan.walls.push_back({a, b, 2 * kOuterHalf, faceOf(h.rooms[i], k, style), false, {}, 0});
					between[i][i].push_back(plan.walls.size() - 1);  // outer walls of room i
					h.rooms[i].outer[static_cast<size_t>(k)] = true;
				}
				s = std::max(s, c1);
			}
		}
	return between;
}

/** The doorway's centre, and its open leaf, keep clear of every other
 * doorway's (a leaf standing in another doorway would shut it). */
bool clearOfOtherDoorways(const FloorPlan& plan, const Opening& o)
{
	const auto centre = [&](const Opening& d) { return alongWall(plan.walls[d.wall], 0.5 * (d.s0 + d.s1)); };
	const auto [hinge, end] = doorLeaf(plan, o);
	for (const Opening& d : plan.openings)
	{
		if (d.kind != Opening::Kind::Doorway) continue;
		const auto [h2, e2] = doorLeaf(plan, d);
		if (pointSegmentDistance(centre(d), hinge, end) < 0.5 || pointSegmentDistance(centre(o), h2, e2) < 0.5) return false;
	}
	return true;
}

/** A doorway near one end of the longest wall between two rooms (often
 * beside a corner, as in real homes), its leaf opening into the room on
 * the wall's front side if leafToFront. */
void addDoorway(FloorPlan& plan, const std::vector<size_t>& walls, bool leafToFront, const HomeStyle& style, SeededRandom& rng)
{
	size_t best = walls[0];
	for (size_t w : walls)
		if ((plan.walls[w].b - plan.walls[w].a).norm() > (plan.walls[best].b - plan.walls[best].a).norm()) best = w;
	const double len = (plan.walls[best].b - plan.walls[best].a).norm(), width = rng.uniform(0.82, 0.92);
	if (len < width + 0.6) return;
	Opening o;
	o.kind = Opening::Kind::Doorway;
	o.wall = best;
	o.z0 = 0, o.z1 = 2.05;
	o.texture = materialRef(style.door);
	o.hasLeaf = true;
	o.leafToFront = leafToFront;
	for (int attempt = 0; attempt < 20; attempt++)
	{
		const double nearEnd = rng.uniform(0.3, 0.5);
		const double s0 = attempt < 10 && rng.chance(0.75) ? (rng.chance(0.5) ? nearEnd : len - width - nearEnd)
														   : rng.uniform(0.3, len - width - 0.3);
		o.s0 = s0, o.s1 = s0 + width;
		o.hingeAtS0 = s0 < len / 2;  // hinged on the corner side, the leaf along the side wall
		if (!clearOfOtherDoorways(plan, o)) continue;
		plan.openings.push_back(o);
		return;
	}
}

void addWindows(FloorPlan& plan, size_t wall, RoomKind kind, const HomeStyle& style, SeededRandom& rng)
{
	const double len = (plan.walls[wall].b - plan.walls[wall].a).norm();
	if (len < 1.8 || (kind == RoomKind::Hall && !rng.chance(0.4))) return;
	const int count = len > 4.5 && rng.chance(0.6) ? 2 : 1;
	for (int i = 0; i < count; i++)
	{
		const double width = std::min(rng.uniform(0.9, 1.5), len / count - 0.7);
		const double centre = len * (i + 0.5) / count + rng.uniform(-0.15, 0.15);
		Opening o;
		o.kind = Opening::Kind::Window;
		o.wall = wall;
		o.s0 = centre - width / 2, o.s1 = centre + width / 2;
		o.z0 = rng.uniform(0.8, 1.0), o.z1 = std::min(plan.ceilingHeight - 0.25, rng.uniform(2.05, 2.2));
		o.texture = rng.pick(style.views);
		plan.openings.push_back(o);
	}
}
}  // namespace

Eigen::Vector2d HomeRoom::innerLo() const
{
	return lo + Eigen::Vector2d(outer[3] ? kOuterHalf : kInnerHalf, outer[0] ? kOuterHalf : kInnerHalf);
}

Eigen::Vector2d HomeRoom::innerHi() const
{
	return hi - Eigen::Vector2d(outer[1] ? kOuterHalf : kInnerHalf, outer[2] ? kOuterHalf : kInnerHalf);
}

HomeLayout buildHomeLayout(FloorPlan& plan, const HomeStyle& style, SeededRandom& rng)
{
	Eigen::Vector2d size;
	HomeLayout h = rng.chance(0.6) ? hallwayHome(rng, size) : openPlanHome(rng, size);
	for (size_t i = 0; i < h.rooms.size(); i++)
	{
		HomeRoom& r = h.rooms[i];
		r.paint = style.paints[i % style.paints.size()];
		const bool papered = r.kind == RoomKind::Living || r.kind == RoomKind::LivingKitchen || r.kind == RoomKind::Bedroom;
		if (papered && rng.chance(0.35)) r.featureWall = rng.integer(0, 3);
	}
	const auto between = buildWalls(plan, h, style);
	for (size_t i = 0; i < h.rooms.size(); i++)
	{
		if (i != h.hub && !between[i][h.hub].empty())
			addDoorway(plan, between[i][h.hub], i < h.hub, style, rng);  // the leaf opens into room i
		for (size_t w : between[i][i]) addWindows(plan, w, h.rooms[i].kind, style, rng);
	}
	// The living room and the kitchen beside it often open into each other too.
	for (size_t i = 0; i < h.rooms.size(); i++)
		for (size_t j = i + 1; j < h.rooms.size(); j++)
			if (i != h.hub && j != h.hub && !between[i][j].empty() && h.rooms[i].kind == RoomKind::Living &&
				h.rooms[j].kind != RoomKind::Bedroom && rng.chance(0.5))
				addDoorway(plan, between[i][j], true, style, rng);
	for (size_t i = 0; i < plan.walls.size(); i++) plan.walls[i].line = static_cast<int>(i + 1);
	return h;
}
}  // namespace vslam::world
