# SPDX-License-Identifier: MIT
# make install's layout, installed into a temporary prefix: the programs run, the package imports
# from <prefix>/lib/pythonX.Y/dist-packages and finds the installed worlds, the installed editor
# finds its default world there.
import os
import subprocess
import sys

import pytest

from conftest import BIN

BUILD = BIN.parent


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    prefix = tmp_path_factory.mktemp("prefix")
    subprocess.run(["cmake", "--install", str(BUILD), "--prefix", str(prefix), "--strip"],
                   check=True, capture_output=True)
    return prefix


def site_packages(prefix):
    return prefix / "lib" / f"python{sys.version_info[0]}.{sys.version_info[1]}" / "dist-packages"


def test_the_installed_package_imports_and_simulates_an_installed_world(prefix):
    script = ("import lamina, sys; "
              "w = lamina.WorldModel(str(lamina.WORLDS / 'klampt' / 'athlete_fractal_1.xml')); "
              "s = lamina.Simulator(w); s.simulate(0.05); "
              "print(lamina.__file__); print(lamina.WORLDS); print(s.getTime())")
    env = dict(os.environ, PYTHONPATH=str(site_packages(prefix)))
    out = subprocess.run([sys.executable, "-c", script], env=env, cwd=prefix, check=True,
                         capture_output=True, text=True).stdout.split("\n")
    assert out[0].startswith(str(site_packages(prefix) / "lamina"))
    assert out[1] == str(prefix / "share" / "lamina" / "worlds")
    assert float(out[2]) == pytest.approx(0.05)
    for module in ("_lamina", "_render", "_window"):
        assert list((site_packages(prefix) / "lamina").glob(module + ".*.so")), module
    # an installed example runs against the installed worlds
    example = prefix / "share" / "lamina" / "examples" / "python" / "kinematic_push.py"
    out = subprocess.run([sys.executable, str(example)], env=env, check=True,
                         capture_output=True, text=True).stdout
    assert "pusher x: 0.6000 m" in out


def test_the_installed_programs_run_on_the_installed_worlds(prefix):
    world = prefix / "share" / "lamina" / "worlds" / "klampt" / "athlete_fractal_1.xml"
    assert world.is_file()
    info = subprocess.run([str(prefix / "bin" / "lamina-headless"), "info", str(world)],
                          check=True, capture_output=True, text=True).stdout
    assert "athlete" in info.lower()
    # the installed editor opens the installed default world (its --help shows the default)
    usage = subprocess.run([str(prefix / "bin" / "lamina"), "--help"], check=True,
                           capture_output=True, text=True).stdout
    assert str(world) in usage
