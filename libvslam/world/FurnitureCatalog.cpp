#include <libvslam/world/FurnitureCatalog.h>

namespace vslam::world
{
namespace
{
struct Row
{
	const char* name;
	FurnitureRole role;
	const char* model;  //!< under kFurnitureArchiveDir
	double widthCm, depthCm, heightCm, elevationCm;
	std::vector<double> rotation;
};

// Sizes, elevations and rotations as the package's
// PluginFurnitureCatalog.properties give them (cm).
const Row kRows[] = {
	{"sofa_beige", FurnitureRole::Sofa, "BlendSwap-CC-0.sh3f/blendswap-cc-0/sofa2/sofa2.obj", 166.9, 74.7, 84.8, 0, {}},
	{"sofa_chesterfield", FurnitureRole::Sofa, "BlendSwap-CC-0.sh3f/blendswap-cc-0/winchesterSofa/winchesterSofa.obj", 231.9, 93.8, 80.4, 0, {}},
	{"sofa_midcentury", FurnitureRole::Sofa, "KatorLegaz.sh3f/katorlegaz/mid-century-sofa/mid-century-sofa.obj", 199.0, 84.0, 80.0, 0, {}},
	{"sofa_leather", FurnitureRole::Sofa, "Scopia.sh3f/scopia/leather_sofa/leather_sofa.obj", 192.5, 90.3, 100.1, 0, {}},
	{"sofa_three_seats", FurnitureRole::Sofa, "Scopia.sh3f/scopia/sofa_white_beige/sofa_white_beige.obj", 173.8, 81.6, 85.0, 0, {}},
	{"sofa_burlap", FurnitureRole::Sofa, "Scopia.sh3f/scopia/burlap_sofa/burlap_sofa.obj", 170.0, 90.0, 79.7, 0, {}},
	{"armchair_chesterfield", FurnitureRole::Armchair, "BlendSwap-CC-0.sh3f/blendswap-cc-0/winchesterArmchair/winchesterArmchair.obj", 112, 93.4, 80.4, 0, {}},
	{"armchair_midcentury", FurnitureRole::Armchair, "KatorLegaz.sh3f/katorlegaz/mid-century-chair/mid-century-chair.obj", 73.5, 84.4, 80.0, 0, {}},
	{"armchair_wing", FurnitureRole::Armchair, "Scopia.sh3f/scopia/armchair/armchair.obj", 78.8, 77.7, 100.1, 0, {}},
	{"armchair_modern", FurnitureRole::Armchair, "Scopia.sh3f/scopia/armchair2/armchair2.obj", 72.8, 81.2, 97.0, 0, {}},
	{"coffee_table_wood", FurnitureRole::CoffeeTable, "Scopia.sh3f/scopia/saloon_table/saloon_table.obj", 143.9, 64.1, 51.1, 0, {0, 0, -1, 0, 1, 0, 1, 0, 0}},
	{"coffee_table_iron", FurnitureRole::CoffeeTable, "Scopia.sh3f/scopia/table_wood_and_iron/table_wood_and_iron.obj", 121.4, 75.9, 50.3, 0, {}},
	{"coffee_table_small", FurnitureRole::CoffeeTable, "Scopia.sh3f/scopia/coffee-table2/coffee-table2.obj", 123.8, 51.2, 47.7, 0, {}},
	{"tv_stand", FurnitureRole::TvStand, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/tvStand/tvStand.obj", 135.1, 46.5, 52.6, 0, {}},
	{"tv_wall_unit", FurnitureRole::TvStand, "Scopia.sh3f/scopia/contemp_living_room/contemp_living_room.obj", 330.9, 40.3, 199.5, 0, {}},
	{"tv_flat", FurnitureRole::Tv, "BlendSwap-CC-0.sh3f/blendswap-cc-0/led_tv/led_tv.obj", 77.5, 14.2, 50.8, 0, {}},
	{"bookcase_books", FurnitureRole::Bookcase, "KatorLegaz.sh3f/katorlegaz/full-bookcase/full-bookcase.obj", 89.8, 34.7, 221.0, 0, {}},
	{"bookcase_glass", FurnitureRole::Bookcase, "Scopia.sh3f/scopia/dining_room/dining_room.obj", 255.6, 36.4, 175.0, 0, {}},
	{"bookcase_low", FurnitureRole::Bookcase, "BlendSwap-CC-0.sh3f/blendswap-cc-0/bookcase/bookcase.obj", 91.9, 36.5, 147.2, 0, {}},
	{"bookcase_wide", FurnitureRole::Bookcase, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/bookcase/bookcase.obj", 166.4, 33.1, 186.4, 0, {}},
	{"shelves_tall", FurnitureRole::Bookcase, "Scopia.sh3f/scopia/kids_shelves/kids_shelves.obj", 101.0, 42.4, 190.7, 0, {}},
	{"fireplace", FurnitureRole::Fireplace, "Scopia.sh3f/scopia/fireplace1/fireplace1.obj", 115.4, 35.1, 105, 0, {}},
	{"piano_upright", FurnitureRole::Piano, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/piano/piano.obj", 141.4, 54.3, 138.4, 0, {}},
	{"plant_yucca", FurnitureRole::Plant, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/yuccaPlant/yuccaPlant.obj", 107.9, 102.4, 180, 0, {}},
	{"plant_ficus", FurnitureRole::Plant, "Scopia.sh3f/scopia/ficus/ficus.obj", 42.5, 41.5, 82.4, 0, {}},
	{"plant_palm", FurnitureRole::Plant, "BlendSwap-CC-0.sh3f/blendswap-cc-0/plant/plant.obj", 81.8, 69, 117.1, 0, {}},
	{"plant_tree", FurnitureRole::Plant, "BlendSwap-CC-0.sh3f/blendswap-cc-0/decorativePlant/decorativePlant.obj", 55.9, 60.2, 103.1, 0, {}},
	{"plant_spathiphyllum", FurnitureRole::Plant, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/spatifilum/spatifilum.obj", 79.8, 74.9, 87.5, 0, {}},
	{"floor_lamp", FurnitureRole::FloorLamp, "Scopia.sh3f/scopia/living_lamp/living_lamp.obj", 39.6, 58.3, 142.9, 0, {0, 0, -1, 0, 1, 0, 1, 0, 0}},
	{"ceiling_lamp", FurnitureRole::CeilingLamp, "Scopia.sh3f/scopia/ceiling-lamp/ceiling-lamp.obj", 30, 30, 5.4, 244.6, {}},
	{"pendant_lamp", FurnitureRole::CeilingLamp, "BlendSwap-CC-0.sh3f/blendswap-cc-0/lamp2/lamp2.obj", 53.4, 51.3, 63.4, 186.6, {}},
	{"dining_table_wood", FurnitureRole::DiningTable, "Scopia.sh3f/scopia/table4/table4.obj", 140.0, 90.0, 75.0, 0, {0, 0, 1, 0, 1, 0, -1, 0, 0}},
	{"dining_table_pear", FurnitureRole::DiningTable, "Scopia.sh3f/scopia/wooden_office_pear_table_rect/wooden_office_pear_table_rect.obj", 160.0, 80.0, 75.4, 0, {}},
	{"dining_table_round", FurnitureRole::DiningTable, "BlendSwap-CC-0.sh3f/blendswap-cc-0/oakTable/oakTable.obj", 124, 124, 74.1, 0, {}},
	{"kitchen_table_white", FurnitureRole::DiningTable, "Scopia.sh3f/scopia/white_kitchen_table/white_kitchen_table.obj", 110.0, 70.1, 75.0, 0, {}},
	{"chair_oak", FurnitureRole::Chair, "BlendSwap-CC-0.sh3f/blendswap-cc-0/oakChair/oakChair.obj", 49.1, 61.2, 117.8, 0, {}},
	{"chair_wood", FurnitureRole::Chair, "Scopia.sh3f/scopia/chair3/chair3.obj", 52.2, 57.6, 85.9, 0, {}},
	{"chair_white", FurnitureRole::Chair, "Scopia.sh3f/scopia/white_kitchen_chair/white_kitchen_chair.obj", 42.7, 46.9, 86.0, 0, {}},
	{"chair_thonet", FurnitureRole::Chair, "BlendSwap-CC-0.sh3f/blendswap-cc-0/thonet/thonet.obj", 54.7, 57.7, 75.4, 0, {}},
	{"bed_double", FurnitureRole::Bed, "Scopia.sh3f/scopia/bed1/bed1.obj", 170.5, 216.5, 110.8, 0, {}},
	{"bed_quilt", FurnitureRole::Bed, "BlendSwap-CC-0.sh3f/blendswap-cc-0/bedWithTexture/bedWithTexture.obj", 198, 226.36, 76.5, 0, {}},
	{"bed_wood", FurnitureRole::Bed, "BlendSwap-CC-0.sh3f/blendswap-cc-0/bed3/bed3.obj", 202.2, 228.2, 114.2, 0, {}},
	{"bed_single", FurnitureRole::Bed, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/juniorBed/juniorBed.obj", 105.7, 197.8, 65.6, 0, {}},
	{"bedside_table", FurnitureRole::BedsideTable, "BlendSwap-CC-0.sh3f/blendswap-cc-0/bedsideTable2/bedsideTable2.obj", 48.55, 48.1, 45.4, 0, {}},
	{"bedside_table_light", FurnitureRole::BedsideTable, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/bedsideTable/bedsideTable.obj", 50.0, 41.4, 48.0, 0, {}},
	{"wardrobe_wood", FurnitureRole::Wardrobe, "Scopia.sh3f/scopia/wardrobe1/wardrobe1.obj", 217.4, 53.0, 200.0, 0, {}},
	{"wardrobe_sliding", FurnitureRole::Wardrobe, "BlendSwap-CC-0.sh3f/blendswap-cc-0/wardrobeWithSlidingDoors/wardrobeWithSlidingDoors.obj", 200, 66, 236.4, 0, {}},
	{"wardrobe_oak", FurnitureRole::Wardrobe, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/wardrobe/wardrobe.obj", 92.1, 68.0, 200.0, 0, {}},
	{"dresser", FurnitureRole::Dresser, "Scopia.sh3f/scopia/dressing-table/dressing-table.obj", 85.7, 46.5, 135.9, 0, {}},
	{"desk_wood", FurnitureRole::Desk, "Scopia.sh3f/scopia/kids_wooden_desk/kids_wooden_desk.obj", 100.4, 61.8, 74.6, 0, {}},
	{"desk_simple", FurnitureRole::Desk, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/simpleDesk/simpleDesk.obj", 140.1, 81.1, 72.0, 0, {}},
	{"desk_chair", FurnitureRole::DeskChair, "Scopia.sh3f/scopia/office_chair/office_chair.obj", 63.5, 63.7, 100, 0, {}},
	{"kitchen_lower", FurnitureRole::KitchenLower, "BlendSwap-CC-0.sh3f/blendswap-cc-0/lowerCabinet/lowerCabinet.obj", 60, 61.2, 88.5, 0, {}},
	{"kitchen_drawers", FurnitureRole::KitchenLower, "BlendSwap-CC-0.sh3f/blendswap-cc-0/drawersCabinet/drawersCabinet.obj", 60, 61.2, 88.5, 0, {}},
	{"kitchen_sink", FurnitureRole::KitchenSink, "BlendSwap-CC-0.sh3f/blendswap-cc-0/sinkCabinet/sinkCabinet.obj", 60, 61.2, 121.2, 0, {}},
	{"kitchen_stove", FurnitureRole::KitchenStove, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/largeStove/largeStove.obj", 103.9, 72.3, 85.2, 0, {}},
	{"kitchen_tall", FurnitureRole::KitchenTall, "BlendSwap-CC-0.sh3f/blendswap-cc-0/highCabinet/highCabinet.obj", 60, 61.2, 217, 0, {}},
	{"fridge", FurnitureRole::KitchenTall, "BlendSwap-CC-0.sh3f/blendswap-cc-0/refrigerator/refrigerator.obj", 90, 95.9, 172.3, 0, {}},
	{"kitchen_upper", FurnitureRole::KitchenUpper, "BlendSwap-CC-0.sh3f/blendswap-cc-0/upperCabinet/upperCabinet.obj", 60, 41, 72, 145, {}},
	{"washing_machine", FurnitureRole::Appliance, "Scopia.sh3f/scopia/clothes_washing_machine/clothes_washing_machine.obj", 59, 60.1, 84.2, 0, {}},
	{"radiator_panel", FurnitureRole::Radiator, "BlendSwap-CC-0.sh3f/blendswap-cc-0/radiator/radiator.obj", 140.3, 24.7, 73.1, 0, {}},
	{"radiator_column", FurnitureRole::Radiator, "BlendSwap-CC-0.sh3f/blendswap-cc-0/radiator3/radiator3.obj", 55.4, 20.7, 64.3, 0, {}},
	{"radiator_modern", FurnitureRole::Radiator, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/modernRadiator/modernRadiator.obj", 50.4, 11.6, 60, 12, {}},
	{"door_wood", FurnitureRole::ClosedDoor, "Scopia.sh3f/scopia/puerta/puerta.obj", 87.0, 13.7, 210.0, 0, {}},
	{"door_white", FurnitureRole::ClosedDoor, "Scopia.sh3f/scopia/door/door.obj", 96, 17.5, 210, 0, {}},
	{"person_woman_1", FurnitureRole::Person, "Reallusion.sh3f/reallusion/female01/female01.obj", 46.6, 45.5, 165.5, 0, {}},
	{"person_woman_2", FurnitureRole::Person, "Reallusion.sh3f/reallusion/female02/female02.obj", 53.0, 45.2, 168.2, 0, {}},
	{"person_woman_3", FurnitureRole::Person, "Reallusion.sh3f/reallusion/female03/female03.obj", 52.0, 49.3, 162.5, 0, {}},
	{"person_man_1", FurnitureRole::Person, "Reallusion.sh3f/reallusion/male01/male01.obj", 61.0, 40.4, 186.2, 0, {}},
	{"person_man_2", FurnitureRole::Person, "Reallusion.sh3f/reallusion/male02/male02.obj", 80.6, 42.9, 182.5, 0, {}},
	{"person_man_3", FurnitureRole::Person, "Reallusion.sh3f/reallusion/male03/male03.obj", 55.7, 39.1, 184.0, 0, {}},
	{"person_boy", FurnitureRole::Person, "Reallusion.sh3f/reallusion/boyStanding/boyStanding.obj", 56.9, 31, 161.8, 0, {}},
	{"person_girl", FurnitureRole::Person, "Reallusion.sh3f/reallusion/girlStanding/girlStanding.obj", 41, 31.5, 156.1, 0, {}},
	{"decor_vase", FurnitureRole::Decor, "Scopia.sh3f/scopia/vase1/vase1.obj", 22.7, 22.7, 30.0, 0, {}},
	{"decor_vase_round", FurnitureRole::Decor, "Scopia.sh3f/scopia/vase2/vase2.obj", 27.2, 27.2, 30.0, 0, {}},
	{"decor_vase_tall", FurnitureRole::Decor, "Scopia.sh3f/scopia/vase3/vase3.obj", 23.5, 23.5, 50.9, 0, {}},
	{"decor_teapot", FurnitureRole::Decor, "Scopia.sh3f/scopia/teapot/teapot.obj", 21.7, 14.7, 21.3, 0, {}},
	{"decor_radio", FurnitureRole::Decor, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/radio/radio.obj", 30.7, 8.4, 26.3, 0, {}},
	{"decor_stereo", FurnitureRole::Decor, "Scopia.sh3f/scopia/mini_stereo/mini_stereo.obj", 48.9, 21, 21, 0, {}},
	{"decor_laptop", FurnitureRole::Decor, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/laptop/laptop.obj", 33.9, 25.3, 26.6, 0, {}},
	{"decor_table_lamp", FurnitureRole::Decor, "Scopia.sh3f/scopia/table_lamp/table_lamp.obj", 20.0, 20.0, 50.1, 0, {}},
	{"decor_little_lamp", FurnitureRole::Decor, "Scopia.sh3f/scopia/little_lamp1/little_lamp1.obj", 33.1, 33.1, 41.9, 0, {}},
	{"decor_desk_lamp", FurnitureRole::Decor, "BlendSwap-CC-0.sh3f/blendswap-cc-0/desklamp/desklamp.obj", 24.4, 24.4, 40, 0, {}},
	{"decor_little_plant", FurnitureRole::Decor, "BlendSwap-CC-0.sh3f/blendswap-cc-0/littlePlant/littlePlant.obj", 26.6, 26.6, 23.2, 0, {}},
	{"decor_succulent", FurnitureRole::Decor, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/succulentPlant/succulentPlant.obj", 13.69006, 12.89416, 11.3663, 0, {}},
	{"decor_frame", FurnitureRole::Decor, "Scopia.sh3f/scopia/frame1/frame1.obj", 14.5, 14.5, 19.6, 0, {}},
	{"decor_frame_small", FurnitureRole::Decor, "Scopia.sh3f/scopia/frame2/frame2.obj", 14.5, 14.5, 19.9, 0, {}},
	{"decor_candle", FurnitureRole::Decor, "Scopia.sh3f/scopia/complements2/complements2.obj", 13.0, 13.0, 15.0, 0, {}},
	{"decor_coffee_machine", FurnitureRole::KitchenDecor, "Scopia.sh3f/scopia/coffee_machine/coffee_machine.obj", 58.2, 40.2, 36.4, 0, {}},
	{"decor_microwave", FurnitureRole::KitchenDecor, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/microwave/microwave.obj", 40.2, 35.8, 24.75, 0, {}},
	{"decor_bread_box", FurnitureRole::KitchenDecor, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/breadBox/breadBox.obj", 56.2, 27.5, 27.5, 0, {}},
	{"decor_kitchen_tools", FurnitureRole::KitchenDecor, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/kitchenTools/kitchenTools.obj", 44.0, 9.8, 31.6, 0, {}},
	{"decor_utensils", FurnitureRole::KitchenDecor, "BlendSwap-CC-BY.sh3f/blendswap-cc-by/utensilsPot/utensilsPot.obj", 12.2, 11.1, 40.2, 0, {}},
	{"decor_bowl", FurnitureRole::KitchenDecor, "KatorLegaz.sh3f/katorlegaz/bowl/bowl.obj", 44.8, 35.0, 17.0, 0, {}},
	{"switch_square", FurnitureRole::Switch, "Scopia.sh3f/scopia/square-switch/square-switch.obj", 8.5, 1.1, 8.5, 115, {}},
	{"switch_double", FurnitureRole::Switch, "Scopia.sh3f/scopia/square-double-switch/square-double-switch.obj", 8.5, 1.1, 8.5, 115, {}},
	{"clock_cuckoo", FurnitureRole::WallDecor, "BlendSwap-CC-0.sh3f/blendswap-cc-0/cuckooClock/cuckooClock.obj", 26.6, 17.7, 73.8, 100, {}},
	{"shelves_low", FurnitureRole::Bookcase, "BlendSwap-CC-0.sh3f/blendswap-cc-0/shelves/shelves.obj", 79, 39.4, 79, 0, {}},
	{"shelves_vertical", FurnitureRole::Bookcase, "BlendSwap-CC-0.sh3f/blendswap-cc-0/verticalShelves/verticalShelves.obj", 44, 39, 185, 0, {}},
	{"box_cardboard", FurnitureRole::Clutter, "Scopia.sh3f/scopia/cardboard-box/cardboard-box.obj", 55, 35, 30, 0, {}},
	{"basket_clothes", FurnitureRole::Clutter, "Scopia.sh3f/scopia/clothes-basket/clothes-basket.obj", 53.9, 53.8, 67.4, 0, {}},
	{"guitar", FurnitureRole::Clutter, "BlendSwap-CC-0.sh3f/blendswap-cc-0/electricGuitar/electricGuitar.obj", 34.5, 32.1, 110, 0, {}},
	{"speaker", FurnitureRole::Clutter, "BlendSwap-CC-0.sh3f/blendswap-cc-0/speaker3/speaker3.obj", 22.1, 25.4, 55.1, 0, {}},
};
}  // namespace

const std::vector<FurnitureItem>& furnitureCatalog()
{
	static const std::vector<FurnitureItem> items = [] {
		std::vector<FurnitureItem> out;
		for (const Row& r : kRows)
			out.push_back({r.name, r.role, std::string(kFurnitureArchiveDir) + r.model, r.widthCm / 100,
				r.depthCm / 100, r.heightCm / 100, r.elevationCm / 100, r.rotation});
		return out;
	}();
	return items;
}

const FurnitureItem* findFurniture(const std::string& name)
{
	for (const FurnitureItem& item : furnitureCatalog())
		if (item.name == name) return &item;
	return nullptr;
}

std::vector<const FurnitureItem*> furnitureOfRole(FurnitureRole role)
{
	std::vector<const FurnitureItem*> out;
	for (const FurnitureItem& item : furnitureCatalog())
		if (item.role == role) out.push_back(&item);
	return out;
}
}  // namespace vslam::world
