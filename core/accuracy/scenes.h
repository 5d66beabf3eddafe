// SPDX-License-Identifier: MIT
// The scenes of the accuracy suite, one factory each (accuracy_scene.cpp lists them in the
// report's order). Each file states its scene's setup, answer and bars in its own comment.
#pragma once

#include <string>

#include "core/accuracy/accuracy_scene.h"

namespace lamina::core {

AccuracyScene BallisticBoxScene();
/// The block sliding to rest at `degrees` from the contact frame's first axis (0, 22.5, 45).
AccuracyScene SlidingBlockScene(double degrees);
/// The ball with restitution `restitution` ("0.5", "0.9" or "1": the world file's suffix).
AccuracyScene BouncingBallScene(const std::string& restitution);
/// SimBenchmark's "bouncing": 49 balls with restitution 1 dropped from 5 m.
AccuracyScene BouncingBallsScene();
AccuracyScene PendulumScene();
/// Rods hinged end to end, released level: `links` 2 (the double pendulum) or 10.
AccuracyScene LinkedPendulumScene(int links);
AccuracyScene InclineScene();
/// The bowling ball launched without spin, or (`spin`) with Drake's side spin of 8π rad/s about
/// its launch direction, which hooks it.
AccuracyScene SlideToRollScene(bool spin);
AccuracyScene BoxStackScene();
/// 210 boxes in a pyramid with a base of 20.
AccuracyScene PyramidScene();
/// SimBenchmark's "666": 216 frictionless spheres collapsing onto the floor.
AccuracyScene SpherePileScene();
/// SimBenchmark's "Kapla": a tower of 102 blocks in 6 floors.
AccuracyScene KaplaScene();
/// The heavy box (`ratio` kg: 100 or 1000) on the 1 kg box.
AccuracyScene HeavyOnLightScene(int ratio);
AccuracyScene ChainScene();
/// Solver2D's "Bridge": 160 hinged links pinned to the world at both ends.
AccuracyScene BridgeScene();
AccuracyScene StiffnessScene();
AccuracyScene StiffnessDropScene();
/// The balls against thin walls, or (`rods`) the thin rods falling onto thin floors.
AccuracyScene HighSpeedScene(bool rods);
/// The mesh cube on the mesh floor; `variant` "" (2.5 mm padding), "pad0", "pad1" or "pad5"
/// (padding 0, 1, 5 mm).
AccuracyScene MeshJitterScene(const std::string& variant);
/// The mesh cube pressed by a robot's pad on a PID-held prismatic joint.
AccuracyScene GripperPadScene();
/// The open tray with a scanned bottom on the mesh floor.
AccuracyScene ScannedTrayScene();
/// The soft tessellated ball resting with maxContacts `max_contacts` (4, 20 or 100).
AccuracyScene SoftBallScene(int max_contacts);

}  // namespace lamina::core
