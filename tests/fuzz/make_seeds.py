#!/usr/bin/env python3
"""Rebuilds the generated seeds of tests/fuzz/corpus/ from the valid inputs of the project.

    tests/fuzz/make_seeds.py SPHJET_BINARY [SHARED_DIR]

legacy/  the hand-written small_*.txt (kept), copies of the legacy runs' case files
         (SHARED_DIR/legacy/*/*.txt, default ../shared relative to the repository)
indat/   for each small_*.txt legacy seed: `sphjet gen`, then INDAT, IPART,
         NORMALS.init and gate joined at the marker lines of fuzz_harness.hpp, plus the INDAT alone
modern/  every cases/**/*.toml with overrides that coarsen the spacing (five to ten times,
         so that the generator stays fast), the examples of cases/CASE_FORMAT.md, and one
         seed with overrides of every kind (a table element, a bare word, a boolean), and
         seeds overriding the keys of [nozzle], [breakup], the axisymmetric [domain],
         [[fluid.cylinder]], a disc's lattice and [surface_tension] (overrides_*.toml)

The tests/data/bad_cases files are used where they are (tools/fuzz.sh, the mutation test).
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
CORPUS = HERE / "corpus"


def legacy(shared: pathlib.Path) -> None:
    for src in sorted(shared.glob("legacy/*/*.txt")):
        if src.name in ("front.txt", "stdout.txt"):
            continue
        shutil.copyfile(src, CORPUS / "legacy" / f"shared_{src.name}")


def indat(sphjet: str) -> None:
    for case in sorted((CORPUS / "legacy").glob("small_*.txt")):
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([sphjet, "gen", str(case), "-o", tmp], check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            t = pathlib.Path(tmp)
            text = (t / "INDAT").read_text()
            (CORPUS / "indat" / f"{case.stem}_indat_only").write_text(text)
            text += "%%IPART%%\n" + (t / "IPART").read_text()
            if (t / "NORMALS.init").exists():
                text += "%%NORMALS.init%%\n" + (t / "NORMALS.init").read_text()
            if (t / "gate").exists():
                text += "%%gate%%\n" + (t / "gate").read_text()
            (CORPUS / "indat" / case.stem).write_text(text)


def modern() -> None:
    for src in sorted((ROOT / "cases").glob("**/*.toml")):
        text = src.read_text()
        res = text[text.find("[resolution]"):]
        over = []
        for key in ("dx", "dz"):
            m = re.search(rf"^{key}\s*=\s*([0-9.eE+-]+)", res, re.M)
            if m:
                dx = float(m.group(1))
                factor = 10 if dx < 0.002 else 5
                d0 = re.search(r"^d0\s*=\s*([0-9.eE+-]+)", text, re.M)
                if d0:  # a nozzle keeps at least 2 particles across d0 (d0 / 2 when round)
                    across = float(d0.group(1)) / (4 if "axisymmetric" in text else 2)
                    factor = max(1, min(factor, int(across / dx)))
                over.append(f"resolution.{key}={dx * factor:g}")
        (CORPUS / "modern" / f"{src.parent.name}_{src.stem}.toml").write_text(
            text + "\n#%%OVERRIDES%%\n" + "\n".join(over) + "\n")
    doc = (ROOT / "cases" / "CASE_FORMAT.md").read_text()
    for k, block in enumerate(re.findall(r"```toml\n(.*?)```", doc, re.S)):
        coarse = re.sub(r"^dx = [0-9.]+", "dx = 0.01", block, flags=re.M)
        coarse = re.sub(r"^dz = [0-9.]+", "dz = 0.01", coarse, flags=re.M)
        (CORPUS / "modern" / f"case_format_example_{k}.toml").write_text(coarse)
    (CORPUS / "modern" / "overrides_all_kinds.toml").write_text(
        (CORPUS / "modern" / "case_format_example_0.toml").read_text() +
        "#%%OVERRIDES%%\n"
        "fluid.block[0].u0=0.25\n"
        "surface_tension.sigma = 0.05\n"
        "numerics.kernel=cubic_spline\n"
        "domain.wall_top=true\n"
        "obstacle[0].density=2\n"
        "output.format=\"hdf5\"\n"
        "time.variable_dt=false\n")
    # Overrides of the sections of the jets and of the axisymmetric cases, on the coarse seeds
    # above: every key of [nozzle], [breakup], the axisymmetric [domain], [[fluid.cylinder]],
    # a disc's lattice and [surface_tension].
    with_overrides = {
        "overrides_jet.toml": ("jet_jet.toml", [
            'nozzle.u0=0.3', 'nozzle.x0=0.045', 'nozzle.z0=0.4', 'nozzle.axis="down"',
            'nozzle.d0=0.012', 'nozzle.length_over_d0=10', 'nozzle.walls=false',
            'nozzle.disturbance=0.05', 'nozzle.disturbance_ka=0.5', 'breakup.link_over_h=1.4',
            'breakup.band_over_d0=0.4', 'breakup.check_every=0.01', 'breakup.stop_after=0.1',
            'breakup.remove_drops_below_h=2', 'surface_tension.delta="colour_gradient"']),
        "overrides_round_jet.toml": ("round_jet_round_jet.toml", [
            'domain.geometry="axisymmetric"', 'domain.axis_pair="rings"', 'domain.periodic_z=false',
            'nozzle.axis="up"', 'nozzle.z0=0.01', 'nozzle.length_over_d0=4', 'nozzle.walls=true',
            'surface_tension.rings_curvature="own"', 'breakup.remove_drops_below_h=2',
            'breakup.stop_after=0']),
        "overrides_cylinder.toml": ("axisymmetric_rayleigh_plateau.toml", [
            'fluid.cylinder[0].radius=0.008', 'fluid.cylinder[0].eps=-0.1',
            'fluid.cylinder[0].wavelength=0.04', 'fluid.cylinder[0].zmin=0.01',
            'fluid.cylinder[0].zmax=0.08', 'domain.periodic_z=false', 'domain.axis_pair="rings"',
            'resolution.h_over_dx=2', 'surface_tension.rings_curvature="neighbour_mean"',
            'surface_tension.sigma=0.5']),
        "overrides_disc_rings.toml": ("laplace_disc_laplace_disc.toml", [
            'fluid.disc[0].lattice="case"', 'fluid.disc[0].lattice=rings',
            'fluid.disc[0].elongation=-0.2', 'fluid.disc[0].radius=0.03',
            'surface_tension.delta="colour_gradient"', 'surface_tension.sigma=0.072',
            'domain.periodic_z=true']),
        "overrides_sphere.toml": ("axisymmetric_sphere_oscillation.toml", [
            'fluid.disc[0].xc=0', 'fluid.disc[0].elongation=0.1', 'domain.axis_pair="rings"',
            'resolution.h_over_dx=2', 'surface_tension.rings_curvature="own"',
            'domain.geometry=axisymmetric']),
    }
    for name, (seed, over) in with_overrides.items():
        (CORPUS / "modern" / name).write_text(
            (CORPUS / "modern" / seed).read_text() + "\n".join(over) + "\n")


def main() -> None:
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    shared = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else ROOT.parent / "shared"
    for d in ("legacy", "indat", "modern"):
        (CORPUS / d).mkdir(parents=True, exist_ok=True)
    legacy(shared)
    indat(sys.argv[1])
    modern()


if __name__ == "__main__":
    main()
