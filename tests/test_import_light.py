"""`import artipg` and generating objects stay light: the mesh and hull libraries
(trimesh, scipy.spatial) load only when meshes or collision shapes are built, so the
CLI and every worker process start in a fraction of a second."""

import subprocess
import sys

HEAVY = ("trimesh", "scipy.spatial")


def _loaded_after(code: str) -> list[str]:
    script = f"import sys\n{code}\nprint(' '.join(m for m in {HEAVY!r} if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    return out.stdout.split()


def test_generation_and_points_do_not_import_mesh_libraries():
    code = ("import artipg\n"
            "for c in artipg.categories():\n"
            "    artipg.generate(c, 3).sample_points(256, seed=1)")
    assert _loaded_after(code) == []


def test_meshes_still_load_their_libraries_on_demand():
    code = ("import artipg\n"
            "m = artipg.generate('storage_furniture', 0).to_trimesh()\n"
            "assert len(m.faces) > 0")
    assert "trimesh" in _loaded_after(code)
