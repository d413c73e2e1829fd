#!/usr/bin/env python3
"""OpenSees (openseespy) against `pounding` on the block-and-frame row (SPEC §13)
under the simulated record synthetic:2000, with the LINEAR Kelvin contact law.

Model, as a new OpenSees user would write it:
  * 1D model (ndm 1, ndf 1): one node per floor, one fixed ground node;
  * each storey a zeroLength element, Steel01(Fy = k * yield_drift, E0 = k, b = alpha);
  * a lumped mass per floor;
  * Rayleigh damping per building (xi at modes 1 and 2 of that building, on the
    INITIAL stiffness): region with -node (alphaM = a0) and region with -ele
    (betaKinit = a1); zeroLength elements need -doRayleigh 1;
  * one zeroLength ViscoelasticGap per floor pair at equal elevation
    (block floor i -> frame floor i, i = 1..3), K = k_bar, C = 2 zeta sqrt(k_bar m_bar),
    gap = -d (compression-only, negative gap);
  * UniformExcitation with a Path time series (dt 0.005 s, linear between samples,
    zero after the last sample: the same as SPEC §9), factor g = 9.80665 m/s^2;
  * Newmark average acceleration (0.5, 0.25), Newton, NormDispIncr 1e-12;
  * record + tail, duration taken from `pounding run --format json`.

Peaks come from an EnvelopeNode recorder (what a user writes); impacts are counted
from a Node recorder of the paired floors (onsets of u_block - u_frame > gap at
step ends). Both recorders write 17 significant digits.

Pitfalls met: (1) a `region -ele ... -rayleigh` resets the factors of its elements'
nodes too, so a separate `region -node` for alphaM followed by a `region -ele` for
betaKinit silently loses the mass-proportional part (checked on a 2-DOF model): use ONE
region per building with both factors. (2) ViscoelasticGap's tangent is K only and its
force jumps by C*rate at closure, so Newton sometimes cycles between open and closed at
a contact onset; such steps are retried with other algorithms, then 4 sub-steps.
Wall time is that of ops.analyze only (model build and result reading excluded),
with both recorders on (NO_HISTORY=1 drops the pair-history recorder: ~15 % faster,
no impact count). Output: stdout summary and a JSON file (--out, default
opensees-block-and-frame.json in the current directory).

Setup on a Debian machine (OpenSees is not a dependency of the project):
  apt-get install libblas3 liblapack3
  python3 -m venv /tmp/ops-venv && /tmp/ops-venv/bin/pip install openseespy
  cargo build --release
  /tmp/ops-venv/bin/python scripts/opensees/block_and_frame.py --check-no-pounding --ours-newmark

Usage: block_and_frame.py [--dts 1e-3,5e-4,2e-4,1e-4,5e-5] [--repeat 3] [--pounding PATH]
                          [--check-no-pounding] [--ours-newmark]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import openseespy.opensees as ops

G = 9.80665  # m/s^2, the tool's g (src/model/record/mod.rs STANDARD_GRAVITY)
HERE = os.path.dirname(os.path.abspath(__file__))

# --- the row, copied from presets/buildings/block-and-frame.toml -------------------
BUILDINGS = [
    dict(name="block", mass=[5.0e5, 5.0e5, 4.0e5], stiffness=[1.2e9, 1.0e9, 0.8e9],
         yield_drift=0.008, alpha=0.05, damping=0.05),
    dict(name="frame", mass=[3.0e5] * 7 + [2.5e5],
         stiffness=[3.0e8, 2.8e8, 2.6e8, 2.4e8, 2.2e8, 2.0e8, 1.8e8, 1.6e8],
         yield_drift=0.016, alpha=0.05, damping=0.05),
]
GAP = 0.005          # m
K_BAR = 2.0e10       # N/m, joint stiffness (Kelvin k_bar)
RESTITUTION = 0.65
HEIGHT = 3.2         # every storey of both buildings: floors 1..3 pair up


def kelvin_zeta(e):
    """SPEC §4: zeta = -ln e / sqrt(pi^2 + ln^2 e) (src/model/contact.rs kelvin_damping_ratio)."""
    l = math.log(e)
    return -l / math.sqrt(math.pi ** 2 + l * l)


def kelvin_pairs():
    """Per floor pair: (floor, m_bar, k_bar, c) with c = 2 zeta sqrt(k_bar m_bar) (SPEC §13)."""
    z = kelvin_zeta(RESTITUTION)
    a, b = BUILDINGS
    out = []
    for i in range(min(len(a["mass"]), len(b["mass"]))):  # equal storey heights: floor i with floor i
        ma, mb = a["mass"][i], b["mass"][i]
        mbar = ma * mb / (ma + mb)
        out.append((i + 1, mbar, K_BAR, 2.0 * z * math.sqrt(K_BAR * mbar)))
    return out


def jacobi_eigvals(A):
    """Eigenvalues of a small symmetric matrix (cyclic Jacobi), ascending."""
    n = len(A)
    A = [row[:] for row in A]
    for _ in range(100):
        off = sum(A[i][j] ** 2 for i in range(n) for j in range(n) if i != j)
        if off < 1e-30 * sum(A[i][i] ** 2 for i in range(n)):
            break
        for p in range(n):
            for q in range(p + 1, n):
                if A[p][q] == 0.0:
                    continue
                th = 0.5 * math.atan2(2 * A[p][q], A[q][q] - A[p][p])
                c, s = math.cos(th), math.sin(th)
                for k in range(n):
                    akp, akq = A[k][p], A[k][q]
                    A[k][p], A[k][q] = c * akp - s * akq, s * akp + c * akq
                for k in range(n):
                    apk, aqk = A[p][k], A[q][k]
                    A[p][k], A[q][k] = c * apk - s * aqk, s * apk + c * aqk
    return sorted(A[i][i] for i in range(n))


def rayleigh(bld):
    """SPEC §13: a0 = 2 xi w1 w2/(w1+w2), a1 = 2 xi/(w1+w2) on the initial stiffness.
    w from M^-1/2 K0 M^-1/2 of the shear building."""
    m, k = bld["mass"], bld["stiffness"]
    n = len(m)
    K = [[0.0] * n for _ in range(n)]
    for i in range(n):
        K[i][i] += k[i]
        if i + 1 < n:
            K[i][i] += k[i + 1]
            K[i][i + 1] = K[i + 1][i] = -k[i + 1]
    A = [[K[i][j] / math.sqrt(m[i] * m[j]) for j in range(n)] for i in range(n)]
    w = [math.sqrt(l) for l in jacobi_eigvals(A)]
    w1, w2 = w[0], (w[1] if n > 1 else w[0])
    xi = bld["damping"]
    return 2 * xi * w1 * w2 / (w1 + w2), 2 * xi / (w1 + w2), [2 * math.pi / x for x in w]


def loadtxt(path):
    with open(path) as f:
        return [[float(x) for x in line.split()] for line in f if line.strip()]


def read_at2(path):
    with open(path) as f:
        lines = f.readlines()
    hdr = lines[3]
    npts = int(hdr.split("NPTS=")[1].split(",")[0])
    dt = float(hdr.split("DT=")[1].split()[0])
    vals = [float(x) for line in lines[4:] for x in line.split()]
    assert len(vals) == npts, (len(vals), npts)
    return dt, vals


def build(acc_g, rec_dt):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(0, 0.0)
    ops.fix(0, 1)
    floors = []  # floors[b][i] = node tag
    mat = 1
    ele = 1
    for b, bld in enumerate(BUILDINGS):
        tags = []
        prev = 0
        for i, (m, k) in enumerate(zip(bld["mass"], bld["stiffness"])):
            n = 100 * (b + 1) + i + 1
            ops.node(n, 0.0)
            ops.mass(n, m)
            ops.uniaxialMaterial("Steel01", mat, k * bld["yield_drift"], k, bld["alpha"])
            ops.element("zeroLength", ele, prev, n, "-mat", mat, "-dir", 1, "-doRayleigh", 1)
            tags.append((n, ele))
            prev = n
            mat += 1
            ele += 1
        floors.append(tags)
        a0, a1, _ = rayleigh(bld)
        # ONE region per building: an -ele region also sets the factors of its elements'
        # nodes, so a second (-node) region for alphaM would be overwritten (or vice versa).
        ops.region(b + 1, "-ele", *[e for _, e in tags], "-rayleigh", a0, 0.0, a1, 0.0)
    gaps = []
    for floor, mbar, k, c in kelvin_pairs():
        if NO_POUNDING:
            ops.node(900 + floor, 0.0); ops.fix(900 + floor, 1)
            gaps.append((floors[0][floor - 1][0], floors[1][floor - 1][0]))
            continue
        ops.uniaxialMaterial("ViscoelasticGap", mat, k, c, -GAP)
        na = floors[0][floor - 1][0]
        nb = floors[1][floor - 1][0]
        # deformation = u_frame - u_block; closed when it is below -GAP
        ops.element("zeroLength", ele, na, nb, "-mat", mat, "-dir", 1)
        gaps.append((na, nb))
        mat += 1
        ele += 1
    ops.timeSeries("Path", 1, "-dt", rec_dt, "-values", *acc_g, "-factor", G)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    return floors, gaps


def analysis(dt):
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")


NO_HISTORY = bool(os.environ.get("NO_HISTORY"))  # timing without the pair-history recorder (no impact count)
NO_POUNDING = bool(os.environ.get("NO_POUNDING"))  # set by --check-no-pounding
FALLBACKS = [("ModifiedNewton", "-initial"), ("NewtonLineSearch",), ("KrylovNewton",)]


def step_with_fallback(dt, depth=0):
    """One step of dt after Newton failed: try other algorithms, then 4 sub-steps."""
    ok = -1
    for alg in FALLBACKS:
        ops.algorithm(*alg)
        ok = ops.analyze(1, dt)
        ops.algorithm("Newton")
        if ok == 0:
            return 0
    if depth < 3:
        print(f"  sub-stepping at t={ops.getTime()!r} dt={dt}", file=sys.stderr)
        for _ in range(4):
            ok = ops.analyze(1, dt / 4)
            if ok != 0:
                ok = step_with_fallback(dt / 4, depth + 1)
            if ok != 0:
                return ok
    return ok


def run_once(acc_g, rec_dt, dt, duration, workdir):
    floors, gaps = build(acc_g, rec_dt)
    allnodes = [n for tags in floors for n, _ in tags]
    env = os.path.join(workdir, "env.out")
    his = os.path.join(workdir, "pairs.out")
    ops.recorder("EnvelopeNode", "-file", env, "-precision", 17, "-node", *allnodes, "-dof", 1, "disp")
    paired = [n for pair in gaps for n in pair]
    if not NO_HISTORY:
        ops.recorder("Node", "-file", his, "-precision", 17, "-node", *paired, "-dof", 1, "disp")
    analysis(dt)
    nsteps = int(math.floor(duration / dt + 1e-9))
    rest = duration - nsteps * dt
    t0 = time.perf_counter()
    fallbacks = 0
    ok = 0
    done = 0
    while done < nsteps:
        ok = ops.analyze(nsteps - done, dt)
        done = int(round(ops.getTime() / dt))
        if ok == 0:
            break
        # the usual OpenSees recipe when Newton stalls: other algorithms, then sub-steps
        ok = step_with_fallback(dt)
        if ok != 0:
            break
        fallbacks += 1
        done = int(round(ops.getTime() / dt))
    if ok == 0 and rest > 1e-12:
        ok = ops.analyze(1, rest)
        if ok != 0:
            ok = step_with_fallback(rest)
    wall = time.perf_counter() - t0
    t_end = ops.getTime()
    ops.wipe()  # flushes and closes the recorders
    if ok != 0:
        raise RuntimeError(f"analysis failed at dt={dt}, t={t_end}")
    absmax = loadtxt(env)[2]  # EnvelopeNode rows: min, max, absmax
    peaks = []
    k = 0
    for tags in floors:
        peaks.append([float(absmax[k + i]) for i in range(len(tags))])
        k += len(tags)
    h = [] if NO_HISTORY else loadtxt(his)  # columns: u_block, u_frame per pair (no -time)
    impacts = []
    for p in range(len(gaps)):
        onsets, was = 0, False
        for row in h:
            closed = row[2 * p] - row[2 * p + 1] - GAP > 0
            onsets += closed and not was
            was = closed
        impacts.append(onsets)
    return dict(dt=dt, wall=wall, t_end=t_end, peaks=peaks, impacts=impacts, fallbacks=fallbacks)


def ours(pounding, excitation, method="exact", dt=None):
    cmd = [pounding, "run", "--buildings", "block-and-frame", "--excitation", excitation,
           "--model", "kelvin", "--method", method, "--format", "json"]
    if dt is not None:
        cmd += ["--dt", repr(dt)]
    d = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    return d, cmd


def error(peaks, ref):
    """Largest |peak - ref peak| over floors, over the building's largest ref peak; max over buildings."""
    per = []
    for p, r in zip(peaks, ref):
        per.append(max(abs(a - b) for a, b in zip(p, r)) / max(r))
    return max(per), per


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pounding", default=os.path.join(HERE, "..", "..", "target", "release", "pounding"))
    ap.add_argument("--dts", default="1e-3,5e-4,2e-4,1e-4,5e-5")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--ours-newmark", action="store_true", help="also run our Newmark at the same dts")
    ap.add_argument("--check-no-pounding", action="store_true",
                    help="first compare both tools without contact (ours: --set joint1.gap=inf) at 1 ms and 0.1 ms")
    ap.add_argument("--out", default="opensees-block-and-frame.json")
    args = ap.parse_args()

    # The record and the recorders' files in a scratch directory, not the repository.
    scratch = tempfile.mkdtemp(prefix="opensees-")
    recdir = os.path.join(scratch, "rec")
    os.makedirs(recdir, exist_ok=True)
    wd = os.path.join(scratch, "work")
    os.makedirs(wd, exist_ok=True)
    at2 = os.path.join(recdir, "synthetic-001.at2")
    # synthetic:2000 = seed 1, 2000 samples at 0.005 s, i.e. 9.995 s (src/model/simulated.rs)
    subprocess.run([args.pounding, "records", "synth", "--count", "1", "--seed", "1",
                    "--duration", "9.995", "--dt", "0.005", "--out", recdir], check=True,
                   capture_output=True)
    rec_dt, acc_g = read_at2(at2)
    assert len(acc_g) == 2000 and rec_dt == 0.005

    syn, cmd_syn = ours(args.pounding, "synthetic:2000")
    rec, cmd_rec = ours(args.pounding, "record:" + at2)
    pk = lambda d: [[f["peak_displacement"] for f in b["floors"]] for b in d["buildings"]]
    same, _ = error(pk(rec), pk(syn))
    print("record check: run with record:FILE vs synthetic:2000, largest relative peak difference "
          f"{same:.2e}, impacts {rec['impacts']} vs {syn['impacts']}")
    duration = syn["duration"]
    ref = pk(syn)
    print(f"duration {duration!r} s (record 9.995 s + tail 4 x T1 of the frame)")

    for bld, b in zip(BUILDINGS, syn["buildings"]):
        a0, a1, T = rayleigh(bld)
        print(f"{bld['name']}: a0 = {a0!r} 1/s, a1 = {a1!r} s; periods (ours) {b['periods'][:2]}, "
              f"(numpy) {T[:2]}")
    print(f"Kelvin: e = {RESTITUTION}, zeta = {kelvin_zeta(RESTITUTION)!r}")
    for floor, mbar, k, c in kelvin_pairs():
        print(f"  pair floor {floor}: m_bar = {mbar!r} kg, K = {k!r} N/m, C = {c!r} N s/m, gap = {-GAP} m")

    if args.check_no_pounding:
        global NO_POUNDING
        d = json.loads(subprocess.run(cmd_syn + ["--set", "joint1.gap=inf"], check=True,
                                      capture_output=True, text=True).stdout)
        NO_POUNDING = True
        for dt in (1e-3, 1e-4):
            r = run_once(acc_g, rec_dt, dt, duration, wd)
            e, per = error(r["peaks"], pk(d))
            print(f"no pounding (ours exact, joint1.gap=inf, {d['impacts']} impacts) vs OpenSees dt={dt:g} "
                  f"without gap elements: error {e:.2e} (block {per[0]:.2e}, frame {per[1]:.2e})", flush=True)
        NO_POUNDING = False

    rows = [dict(tool="pounding", method="exact (reference proxy)", dt=None, error=0.0,
                 wall=syn["elapsed_ms"] / 1e3, impacts=[p["impacts"] for p in syn["pairs"]],
                 peaks=ref)]
    if True:
        for dt in [float(x) for x in args.dts.split(",")]:
            runs = [run_once(acc_g, rec_dt, dt, duration, wd)]
            if runs[0]["wall"] < 10:
                for _ in range(args.repeat - 1):
                    runs.append(run_once(acc_g, rec_dt, dt, duration, wd))
            best = min(r["wall"] for r in runs)
            r = runs[0]
            assert all(x["peaks"] == r["peaks"] for x in runs)
            err, per = error(r["peaks"], ref)
            rows.append(dict(tool="OpenSees " + ops.version(), method="Newmark avg accel + Newton",
                             dt=dt, error=err, error_per_building=per, wall=best,
                             walls=[x["wall"] for x in runs], impacts=r["impacts"], peaks=r["peaks"],
                             t_end=r["t_end"], fallbacks=r["fallbacks"]))
            print(f"OpenSees dt={dt:g}: error {err:.3e} (block {per[0]:.2e}, frame {per[1]:.2e}), "
                  f"wall {best:.3f} s (runs {[round(x['wall'], 3) for x in runs]}), "
                  f"impacts {r['impacts']} (sum {sum(r['impacts'])}), t_end {r['t_end']:.6f}, "
                  f"steps needing the fallback {r['fallbacks']}", flush=True)
            if args.ours_newmark:
                walls = []
                for _ in range(args.repeat):
                    d, _ = ours(args.pounding, "synthetic:2000", "newmark", dt)
                    walls.append(d["elapsed_ms"] / 1e3)
                e2, per2 = error(pk(d), ref)
                rows.append(dict(tool="pounding", method="newmark (located contact)", dt=dt, error=e2,
                                 error_per_building=per2, wall=min(walls),
                                 impacts=[p["impacts"] for p in d["pairs"]], peaks=pk(d)))
                print(f"  ours newmark dt={dt:g}: error {e2:.3e}, {min(walls):.3f} s, "
                      f"impacts {[p['impacts'] for p in d['pairs']]}", flush=True)
    osr = [r for r in rows if r["tool"].startswith("OpenSees")]
    for a, b in zip(osr, osr[1:]):
        print(f"OpenSees observed order {a['dt']:g} -> {b['dt']:g} s: "
              f"{math.log(a['error'] / b['error']) / math.log(a['dt'] / b['dt']):.2f}")
    if len(osr) > 2:
        xs = [math.log(r["dt"]) for r in osr]
        ys = [math.log(r["error"]) for r in osr]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        print(f"OpenSees least-squares order over {len(osr)} steps: {slope:.2f}")
    with open(args.out, "w") as f:
        json.dump(dict(duration=duration, commands=[cmd_syn, cmd_rec], rows=rows), f, indent=1)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
