// Where things are in the islands world, shared by the builder (world.cpp) and the animation
// (motion.cpp). Map coordinates: x east, z south, y up, metres; sea level is y = 0.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace facet::islands::map {

// Between the islands: the ocean and the airplane's circle are centred here.
inline constexpr glm::vec2 kMapCentre{160.0f, 35.0f};

// The start camera stands on the lookout hill of the first island, looking east-north-east:
// the mountains and the canyon on the left, the second island's airfield ahead to the right.
inline constexpr glm::vec2 kLookout{-95.0f, 45.0f};     // the top of the hill
inline constexpr glm::vec2 kStandpoint{-82.0f, 43.0f};  // on its brow, to see down the slope
inline constexpr float kEyeHeight = 1.7f;
inline constexpr glm::vec3 kLookAt{300.0f, -14.0f, 10.0f};
inline constexpr float kFieldOfView = 60.0f;  // vertical, degrees

// The airfield on the second island: a levelled plateau, the runway along Z (so the start
// camera sees it broadside), the apron and the hangar east of it.
inline constexpr float kAirfieldHeight = 3.0f;
inline constexpr glm::vec2 kRunwayCentre{315.0f, 70.0f};
inline constexpr float kRunwayLength = 130.0f, kRunwayWidth = 18.0f;
// Runway and apron float this far above the plateau: several depth-buffer steps even at the
// far end of the view, and far too little to see.
inline constexpr float kPaveLift = 0.15f;

// The flying airplane circles over both islands, high enough to clear the summit.
inline constexpr glm::vec2 kFlightCentre = kMapCentre;
inline constexpr float kFlightRadius = 170.0f;
inline constexpr float kFlightAltitude = 105.0f;
inline constexpr float kFlightSpeed = 42.0f;          // metres per second
inline constexpr float kFlightStartDegrees = -80.0f;  // where it is at t = 0
inline constexpr float kPropellerTurnsPerSecond = 11.0f;

// The boat runs an elongated loop between the islands: across and back.
inline constexpr glm::vec2 kBoatLoopCentre{190.0f, 60.0f};
inline constexpr glm::vec2 kBoatLoopRadii{30.0f, 9.0f};
inline constexpr float kBoatLapSeconds = 24.0f;

// Clouds drift east with the wind and wrap around over this stretch of sky.
inline constexpr float kWind = 3.0f;  // metres per second
inline constexpr float kCloudsWest = -450.0f, kCloudsSpan = 1200.0f;

// Texture scrolling, in texture repeats per second (the river's texture is 8 m long, the
// falls' 6 m): the falls run fast, the river ambles, the sea drifts.
inline constexpr float kFallsScroll = 1.2f;
inline constexpr float kRiverScroll = 0.12f;
inline constexpr glm::vec2 kOceanDrift{0.011f, 0.007f};

}  // namespace facet::islands::map
