#pragma once
// What `pmdplan check --json` prints (and Python's pmdplan.check returns) about a task, built in
// one place: for the start and the goal their validity, colliding pairs, clearance (or
// penetration depth) and palm pose; the straight joint-space segment between them at the motion
// tolerance; and `plan`'s verdict (the grasp rule's refusals, a grasp goal's target and pre-grasp;
// collision/grasp_rule.hpp, planning/grasp_approach.hpp).
//
//   {"task", "start": {valid, collisions, clearance_mm, nearest, palm_position, palm_z_axis},
//    "goal": {... and for a grasp "grasp": target, "pregrasp": {derived, opening, clearance_mm}},
//    "straight_line": {free, first_collision, collisions, states_checked, states_needed, tolerance_mm},
//    "plan": {accepts, refusals: [{field, reason, pairs}]}}
#include <nlohmann/json.hpp>

#include "pmdplan/planning/grasp_approach.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

/// The document (keys sorted, as nlohmann::json keeps them). Throws InputError for a tolerance out
/// of range ("--tolerance-mm"), a robot without a palm link (its URDF, "end_effector") and a
/// straight segment needing more than kMaxValidationStates states (the task file, "start, goal").
nlohmann::json taskCheckJson(const Task& task, double toleranceMm, const GraspSettings& grasp = {});

}  // namespace pmdplan
