"""Files the module writes follow the CLI's output rule: the umask, a replaced file's own mode."""
import os
import stat

import pmdplan


def mode(path):
    return stat.S_IMODE(os.stat(path).st_mode)


def test_a_saved_file_honours_the_umask_and_a_replaced_one_keeps_its_mode(tmp_path):
    model = pmdplan.SynergyModel.default_for("sah_tx90")
    previous = os.umask(0o077)
    try:
        model.save(tmp_path / "private.yaml")
    finally:
        os.umask(previous)
    assert mode(tmp_path / "private.yaml") == 0o600
    secret = tmp_path / "secret.yaml"
    secret.write_text("an earlier model\n")
    os.chmod(secret, 0o600)
    model.save(secret)
    assert mode(secret) == 0o600
    assert "an earlier model" not in secret.read_text()
