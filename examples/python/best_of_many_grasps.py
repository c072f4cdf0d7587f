"""Plan to many grasps of one object and keep the best path.

The candidate grasps are variations of can_on_table's goal: the wrist turned about its last axis
(the can is round) and the hand closed a little more or less along the first PMD. Candidates whose
grasp posture collides are dropped; every other one is planned, and the shortest valid path wins.

    PYTHONPATH=build/python python3 examples/python/best_of_many_grasps.py
"""
import numpy as np

import pmdplan

task = pmdplan.Task.load("can_on_table")
robot = task.robot
synergies = pmdplan.SynergyModel.default_for(robot.name)
checker = pmdplan.CollisionChecker(task)  # reused by every plan (a task's checker fits its replacements)
hand = robot.groups["hand"]
wrist = robot.joint_names.index("tx90_joint_6")

candidates = []
for turn_deg in (-20, -10, 0, 10, 20):
    for closing in (-0.5, 0.0, 0.5):
        goal = task.goal.copy()
        goal[wrist] = np.clip(goal[wrist] + np.radians(turn_deg), robot.lower[wrist], robot.upper[wrist])
        coefficients = synergies.coefficients(goal[hand])
        coefficients[0] += closing * synergies.sigma[0]
        posture = synergies.posture(coefficients)
        thumb = synergies.joint_names.index("thumb_base")
        posture[thumb] = goal[hand][thumb]
        goal[hand] = np.clip(posture, robot.lower[hand], robot.upper[hand])
        candidates.append((turn_deg, closing, goal))

free = [(t, c, g) for t, c, g in candidates if checker.is_valid(g)]
print(f"{len(candidates)} candidate grasps, {len(free)} collision-free")
best = None
for turn_deg, closing, goal in free:
    grasp_task = task.replace(goal=goal, name=f"{task.name}_turn{turn_deg}_close{closing}")
    result = pmdplan.plan(grasp_task, seed=1, time_limit=10)
    if not result.solved or not pmdplan.validate(grasp_task, result.path, closing_from=result.closing_from)["valid"]:
        print(f"  turn {turn_deg:+3d} deg, closing {closing:+.1f} sigma: {result.status}")
        continue
    length = result.statistics["path_length"]
    print(f"  turn {turn_deg:+3d} deg, closing {closing:+.1f} sigma: length {length:.3f}")
    if best is None or length < best[0]:
        best = (length, turn_deg, closing, result)
if best:
    length, turn_deg, closing, result = best
    result.save("best_grasp.path.json")
    print(f"best: turn {turn_deg:+d} deg, closing {closing:+.1f} sigma, length {length:.3f} -> best_grasp.path.json")
