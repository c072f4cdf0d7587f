"""The scripts of examples/python run and write what they say."""
import os
import pathlib
import subprocess
import sys

import pytest

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"


@pytest.mark.parametrize("script, writes", [
    ("plan_builtin_task.py", "can_on_table.path.json"),
    ("best_of_many_grasps.py", "best_grasp.path.json"),
    ("fit_synergies.py", "fitted_synergies.yaml"),
])
def test_example_runs(script, writes, tmp_path):
    done = subprocess.run([sys.executable, str(EXAMPLES / script)], cwd=tmp_path, capture_output=True, text=True,
                          env=dict(os.environ), timeout=600)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / writes).is_file(), done.stdout
