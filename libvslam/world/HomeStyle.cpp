#include <libvslam/core/InputError.h>
#include <libvslam/world/AssetArchive.h>
#include <libvslam/world/HomeStyle.h>

#include <array>

namespace vslam::world
{
namespace
{
const std::string kTextures = "sweethome3d/sweethome3d.jar/com/eteks/sweethome3d/io/resources/textures/";
const std::string kFurniture = "sweethome3d/furniture/";

using Rgb = std::array<double, 3>;
/** Wall paints of real homes: whites, creams, pale colours. */
const std::vector<Rgb> kPaints = {{246, 244, 239}, {240, 234, 222}, {238, 228, 205}, {226, 214, 192}, {216, 216, 212},
	{208, 220, 230}, {214, 226, 208}, {242, 232, 196}, {206, 198, 186}, {236, 220, 214}};

std::string wallpaper(const std::string& name, const std::string& file) { return "wallpapers/" + name + "/contents/images/" + file; }
std::string mate(const std::string& file) { return "backgrounds/mate/" + file; }

/** Outdoor photographs: what a window shows. */
const std::vector<std::string> kViews = {wallpaper("Path", "2560x1600.jpg"), mate("nature/Dune.jpg"),
	mate("nature/GreenMeadow.jpg"), wallpaper("EveningGlow", "2560x1600.jpg"), wallpaper("ColdRipple", "2560x1600.jpg"),
	mate("nature/Storm.jpg"), wallpaper("BytheWater", "2560x1600.jpg"), wallpaper("Kite", "2560x1600.jpg")};

/** Posters, paintings, photographs and prints. */
const std::vector<std::string> kPictures = {wallpaper("Autumn", "2560x1600.jpg"), wallpaper("SafeLanding", "5120x2880.jpg"),
	wallpaper("PastelHills", "3200x2000.jpg"), wallpaper("ColorfulCups", "2560x1600.jpg"),
	wallpaper("FallenLeaf", "2560x1600.jpg"), wallpaper("OneStandsOut", "2560x1600.jpg"), wallpaper("Flow", "5120x2880.jpg"),
	wallpaper("Honeywave", "5120x2880.jpg"), wallpaper("Grey", "2560x1600.jpg"), wallpaper("summer_1am", "2560x1600.jpg"),
	mate("abstract/Elephants.jpg"), mate("nature/Aqua.jpg"), mate("nature/LadyBird.jpg"), mate("nature/FreshFlower.jpg"),
	mate("nature/Garden.jpg"), mate("nature/YellowFlower.jpg"), mate("nature/TwoWings.jpg"), mate("nature/RainDrops.jpg")};

class MaterialMaker
{
   public:
	MaterialMaker(FloorPlan& plan) : m_plan(plan) {}

	int add(const std::string& name, const std::string& file, double w, double h, const Rgb& tint, double contrast)
	{
		Material m;
		m.name = name;
		m.file = checked(file);
		m.tileWidth = w, m.tileHeight = h;
		m.tint = {tint[0] / 255, tint[1] / 255, tint[2] / 255};
		m.contrast = contrast;
		m_plan.materials.push_back(m);
		return static_cast<int>(m_plan.materials.size() - 1);
	}

	TextureRef photo(const std::string& file, double u0 = 0, double v0 = 0, double u1 = 1, double v1 = 1)
	{
		TextureRef t;
		t.file = checked(file);
		t.u0 = u0, t.v0 = v0, t.u1 = u1, t.v1 = v1;
		return t;
	}

   private:
	FloorPlan& m_plan;

	std::string checked(const std::string& file) const
	{
		const std::string path = m_plan.textureDir + "/" + file;
		if (!locateAsset(path))
			throw InputError("home generator: no texture '" + path +
				"' (the packages sweethome3d, sweethome3d-furniture, mate-backgrounds and plasma-workspace-wallpapers provide them)");
		return path;
	}
};
}  // namespace

TextureRef materialRef(int index)
{
	TextureRef t;
	t.material = index;
	return t;
}

TextureRef HomeStyle::floorFor(RoomKind kind) const
{
	switch (kind)
	{
		case RoomKind::Kitchen: return materialRef(tiles);
		case RoomKind::Bedroom: return materialRef(carpet >= 0 ? carpet : woodFloor);
		case RoomKind::Hall: return materialRef(hallFloor);
		default: return materialRef(woodFloor);
	}
}

HomeStyle makeHomeStyle(FloorPlan& plan, size_t rooms, SeededRandom& rng)
{
	MaterialMaker make(plan);
	HomeStyle s;
	// Painted plaster: the roughcast photograph (it tiles without seams), its
	// grain reduced from a textured finish to a nearly smooth one.
	const std::string plaster = kTextures + "roughcast.jpg";
	const double tile = rng.uniform(0.45, 0.7), contrast = rng.uniform(0.1, 0.3);
	for (size_t i = 0; i < rooms; i++)
		s.paints.push_back(make.add("paint" + std::to_string(i + 1), plaster, tile, tile, rng.pick(kPaints), contrast));
	s.ceiling = make.add("ceiling", kTextures + "roughcast.jpg", 0.6, 0.6, {248, 247, 244}, 0.05);
	const bool woodSkirting = rng.chance(0.3);
	s.skirting = woodSkirting ? make.add("skirting", kFurniture + "Scopia.sh3f/scopia/wooden_office_pear_table/pear_wood.jpg", 0.6, 0.6, {255, 255, 255}, 0.6)
							  : make.add("skirting", kTextures + "roughcast.jpg", 0.6, 0.6, {244, 243, 240}, 0.04);
	s.skirtingHeight = rng.uniform(0.06, 0.1);
	s.door = rng.chance(0.5) ? make.add("door", kTextures + "roughcast.jpg", 0.6, 0.6, {242, 242, 238}, 0.05)
							 : make.add("door", kFurniture + "Scopia.sh3f/scopia/puerta/tilewood.jpg", 0.9, 2.1, {255, 255, 255}, 1.0);
	s.woodFloor = rng.chance(0.5) ? make.add("parquet", kTextures + "woodenFloor.jpg", 0.425, 0.425, {255, 255, 255}, 1.0)
								  : make.add("planks", kTextures + "oldWoodenFloor.jpg", 0.269, 0.269, {255, 255, 255}, 1.0);
	struct Tiles { const char* file; double w, h; };
	static const std::vector<Tiles> kTiles = {{"greyTile.jpg", 0.315, 0.315}, {"blackAndWhiteTiles.jpg", 0.7, 0.7},
		{"beigeTile.jpg", 0.2, 0.2}, {"redTiles.jpg", 0.4, 0.4}, {"stoneTiles.jpg", 0.6, 0.4}, {"lightBlueTile.jpg", 0.335, 0.335}};
	const Tiles& t = rng.pick(kTiles);
	s.tiles = make.add("tiles", kTextures + t.file, t.w, t.h, {255, 255, 255}, 1.0);
	static const std::vector<Tiles> kWallTiles = {{"wallBeigeTile.jpg", 0.2, 0.2}, {"blueTiles.jpg", 0.2, 0.2},
		{"smallWhiteBricks.jpg", 0.353, 0.353}, {"lightBlueTile.jpg", 0.2, 0.2}};
	const Tiles& wt = rng.pick(kWallTiles);
	s.wallTiles = make.add("wall_tiles", kTextures + wt.file, wt.w, wt.h, {255, 255, 255}, 1.0);
	struct Paper { const char* file; double tile, contrast; };
	static const std::vector<Paper> kPapers = {{"Scopia.sh3f/scopia/curtain/beige_pattern.jpg", 0.5, 0.8},
		{"Scopia.sh3f/scopia/doll-house/3_green_and_white_lines_wallpaper_little.jpg", 0.45, 0.5},
		{"Scopia.sh3f/scopia/futon/wallpaper-chiyogami.jpg", 0.6, 0.45},
		{"Scopia.sh3f/scopia/futon/wallpaper-japanese-pink-flowers.jpg", 0.6, 0.45}};
	const Paper& paper = rng.pick(kPapers);
	s.wallpaper = make.add("wallpaper", kFurniture + paper.file, paper.tile, paper.tile, {255, 255, 255}, paper.contrast);
	if (rng.chance(0.5))
		s.carpet = make.add("carpet", kFurniture + "BlendSwap-CC-BY.sh3f/blendswap-cc-by/cornerSofa/Fabric_04.jpg", 0.5, 0.5,
			rng.pick(kPaints), 0.5);
	s.hallFloor = rng.chance(0.5) ? s.woodFloor : make.add("hall_tiles", kTextures + "stoneTiles.jpg", 0.6, 0.4, {255, 255, 255}, 1.0);
	for (int i = 0; i < 2; i++) s.views.push_back(make.photo(rng.pick(kViews)));
	for (const std::string& p : kPictures)
	{
		// A part of the picture: a print, a detail, the whole.
		const double w = rng.uniform(0.5, 1.0), h = rng.uniform(0.5, 1.0);
		const double u0 = rng.uniform(0, 1 - w), v0 = rng.uniform(0, 1 - h);
		s.pictures.push_back(make.photo(p, u0, v0, u0 + w, v0 + h));
	}
	s.radiator = rng.pick(furnitureOfRole(FurnitureRole::Radiator));
	return s;
}
}  // namespace vslam::world
