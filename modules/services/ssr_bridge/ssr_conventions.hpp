// BEFT's scene in the SoundScape Renderer's terms (SSR 0.6, its XML network
// interface; see README.md).
//
// SSR's legacy interface works in a plane with x and y in metres and an
// azimuth in degrees counter-clockwise from +x, as BEFT's world frame and
// yaw do: SSR turns an azimuth into its internal rotation by subtracting
// 90 degrees (legacy_orientation.cpp), so that its default reference
// orientation of 90 degrees is its internal identity, the listener looking
// along +y. Nothing has to be rotated or mirrored: a listener with azimuth
// yaw looks where a robot with that yaw looks. Heights are not sent (SSR's
// legacy interface is two-dimensional).
#pragma once

#include <beft/robot_state_t.hpp>

namespace beft::ssr_bridge {

// Where the listener (SSR's reference) is and where it looks: the head sits
// on the platform centre, its nose platform yaw + head yaw from +x.
struct ListenerPose {
  double x = 0, y = 0;  // [m]
  double azimuth = 0;   // SSR's reference azimuth, in [0, 360) [deg]
};
ListenerPose listenerPose(const beft::robot_state_t& robot);

// An angle in degrees brought into [0, 360).
double normalisedDegrees(double degrees);

// A source's volume for SSR, which takes dB and refuses "-inf": 20 log10 of
// the linear level, and kSilentVolumeDb for a level of 0 or less, anything
// quieter than that, or a level that is not finite.
constexpr double kSilentVolumeDb = -120.0;
double volumeDecibels(double linear_level);

}  // namespace beft::ssr_bridge
