"""Plan a built-in task with the paper's planner, validate the path and save it.

    PYTHONPATH=build/python python3 examples/python/plan_builtin_task.py [TASK] [SEED]
"""
import sys

import pmdplan

task = pmdplan.Task.load(sys.argv[1] if len(sys.argv) > 1 else "can_on_table")
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
result = pmdplan.plan(task, "pmd", seed=seed)
if not result.solved:
    sys.exit(f"{task.name}: not solved ({result.status})")
stats = result.statistics
print(f"{task.name}: solved in {stats['planning_time_s']:.3f} s, {stats['roadmap_nodes']} roadmap nodes, "
      f"{result.path.shape[0]} path points, length {stats['path_length']:.3f} (normalised)")
report = pmdplan.validate(task, result.path)
print(f"validated: {'valid' if report['valid'] else 'INVALID'} ({report['states_checked']} states checked)")
print("human-likeness:", {k: round(v, 4) for k, v in pmdplan.human_likeness(task, result.path).items()})
result.save(f"{task.name}.path.json")
print(f"path written to {task.name}.path.json (view it with `pmdplan view`)")
