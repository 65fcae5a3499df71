#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Tessella's P1 solvers against FEniCS/dolfinx 0.5 on the same meshes.

Runs bench/solvers_bench (built from this tree) with --write-meshes, then solves
the same two problems with dolfinx on each written mesh, one process:

  steady  -lap u = 1, u = 0 on x = 0, zero flux elsewhere
  step    one implicit-Euler step, (M/dt + K) u = f, dt = 1e-3, from u = 0

dolfinx: CG + hypre BoomerAMG through PETSc (HMIS coarsening, ext+i
interpolation, P_max 4, strong threshold 0.25 in 2D / 0.5 in 3D, the same
settings as Tessella's AmgCG back-end), relative tolerance 1e-8. It prints
the assembly rate (re-assembly of the stiffness matrix, elements/s) and the
time to solution (matrix set-up + factorisation/AMG set-up + solve) of
each, and the ratios Tessella / dolfinx.

Usage (Debian's python, which has the dolfinx package):
  /usr/bin/python3 bench/dolfinx_compare.py --bench build/bin/solvers_bench [--quick|--full]
      [--backends amg,cholmod,cg,direct] [--threads N]

python3-dolfinx-real (Debian) is installed with apt-get when missing; it is
needed for this comparison only and is not one of Tessella's dependencies.
"""
import argparse
import logging
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time


def ensure_dolfinx():
    try:
        import dolfinx  # noqa: F401
        return
    except ImportError:
        pass
    if sys.executable != "/usr/bin/python3":
        sys.exit("dolfinx_compare: run with Debian's /usr/bin/python3 (python3-dolfinx-real installs there)")
    print("dolfinx_compare: installing python3-dolfinx-real with apt-get", flush=True)
    sudo = [] if os.geteuid() == 0 else ["sudo"]
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(sudo + ["apt-get", "update", "-qq"], check=True, env=env)
    subprocess.run(sudo + ["apt-get", "install", "-y", "-qq", "python3-dolfinx-real"], check=True, env=env)
    os.execv(sys.executable, [sys.executable] + sys.argv)  # fresh interpreter sees the new package


def run_tessella(bench, mesh_dir, full, quick, backends):
    cmd = [bench, "--write-meshes", mesh_dir, "--backends", backends]
    if full:
        cmd.append("--full")
    if quick:
        cmd.append("--quick")
    print("$", " ".join(cmd), flush=True)
    results = []
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True) as p:
        for line in p.stdout:
            if line.startswith("RESULT "):
                results.append(dict(kv.split("=", 1) for kv in line.split()[1:]))
            else:
                print("  tessella|", line.rstrip(), flush=True)
    if p.returncode != 0:
        sys.exit(f"dolfinx_compare: {bench} failed with exit code {p.returncode}")
    return results


def run_dolfinx(mesh_dir, name, dim, nodes_count):
    import numpy as np
    import ufl
    from dolfinx import fem, mesh
    from dolfinx.fem import petsc as fpetsc
    from mpi4py import MPI
    from petsc4py import PETSc

    x = np.fromfile(os.path.join(mesh_dir, name + ".nodes"), dtype="<f8").reshape(-1, 3)[:, :dim].copy()
    cells = np.fromfile(os.path.join(mesh_dir, name + ".cells"), dtype="<i8").reshape(-1, dim + 1)
    assert x.shape[0] == nodes_count
    cell = "triangle" if dim == 2 else "tetrahedron"
    domain = ufl.Mesh(ufl.VectorElement("Lagrange", ufl.Cell(cell, geometric_dimension=dim), 1))
    msh = mesh.create_mesh(MPI.COMM_SELF, cells, x, domain)
    V = fem.FunctionSpace(msh, ("Lagrange", 1))
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    dt = 1e-3
    f = fem.Constant(msh, PETSc.ScalarType(1.0))
    forms = {
        "steady": fem.form(ufl.inner(ufl.grad(u), ufl.grad(v)) * ufl.dx),
        "step": fem.form((u * v / dt + ufl.inner(ufl.grad(u), ufl.grad(v))) * ufl.dx),
    }
    L = fem.form(f * v * ufl.dx)
    facets = mesh.locate_entities_boundary(msh, dim - 1, lambda p: np.isclose(p[0], 0.0))
    bc = fem.dirichletbc(PETSc.ScalarType(0.0), fem.locate_dofs_topological(V, dim - 1, facets), V)
    out = {}
    # Re-assembly of the stiffness matrix (the sparsity pattern exists), as the Tessella figure.
    A = fpetsc.assemble_matrix(forms["steady"], bcs=[bc])
    A.assemble()
    A.zeroEntries()
    t0 = time.perf_counter()
    fpetsc.assemble_matrix(A, forms["steady"], bcs=[bc])
    A.assemble()
    out["assembly"] = time.perf_counter() - t0
    for problem, a in forms.items():
        t0 = time.perf_counter()
        A = fpetsc.assemble_matrix(a, bcs=[bc])
        A.assemble()
        b = fpetsc.assemble_vector(L)
        fpetsc.apply_lifting(b, [a], bcs=[[bc]])
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        fpetsc.set_bc(b, [bc])
        t_matrix = time.perf_counter() - t0
        ksp = PETSc.KSP().create(MPI.COMM_SELF)
        ksp.setOperators(A)
        ksp.setType("cg")
        ksp.setTolerances(rtol=1e-8, atol=0.0, max_it=10000)
        ksp.setNormType(PETSc.KSP.NormType.UNPRECONDITIONED)  # ||r|| / ||b||, as Tessella
        pc = ksp.getPC()
        pc.setType("hypre")
        pc.setHYPREType("boomeramg")
        opts = PETSc.Options()
        opts["pc_hypre_boomeramg_coarsen_type"] = "HMIS"
        opts["pc_hypre_boomeramg_interp_type"] = "ext+i"
        opts["pc_hypre_boomeramg_P_max"] = 4
        opts["pc_hypre_boomeramg_strong_threshold"] = 0.25 if dim == 2 else 0.5
        opts["pc_hypre_boomeramg_relax_type_all"] = "symmetric-SOR/Jacobi"
        pc.setFromOptions()
        ksp.setFromOptions()
        uh = fem.Function(V)
        t0 = time.perf_counter()
        ksp.setUp()
        t_setup = time.perf_counter() - t0
        t0 = time.perf_counter()
        ksp.solve(b, uh.vector)
        t_solve = time.perf_counter() - t0
        if ksp.getConvergedReason() <= 0:
            sys.exit(f"dolfinx_compare: dolfinx CG did not converge on {name} ({problem})")
        out[problem] = dict(matrix=t_matrix, setup=t_setup, solve=t_solve, iterations=ksp.getIterationNumber(),
                            maxu=uh.vector.max()[1])
        ksp.destroy()
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bench", default="build/bin/solvers_bench", help="path to the solvers_bench program")
    ap.add_argument("--full", action="store_true", help="add the ~10^6-node meshes (minutes, several GB)")
    ap.add_argument("--quick", action="store_true", help="~10^4-node meshes only")
    ap.add_argument("--backends", default="amg,cholmod,cg",
                    help="Tessella back-ends to run (solvers_bench --backends; default amg,cholmod,cg)")
    ap.add_argument("--threads", type=int, default=1,
                    help="OMP_NUM_THREADS for both codes (hypre uses OpenMP too; default 1)")
    args = ap.parse_args()
    if not os.access(args.bench, os.X_OK):
        sys.exit(f"dolfinx_compare: {args.bench} is not an executable (build the solvers_bench target)")
    os.environ["OMP_NUM_THREADS"] = str(args.threads)
    ensure_dolfinx()
    logging.disable(logging.INFO)  # dolfinx's form compiler logs every C compile at INFO
    mesh_dir = tempfile.mkdtemp(prefix="tessella_dolfinx_")
    try:
        results = run_tessella(args.bench, mesh_dir, args.full, args.quick, args.backends)
        meshes = {}
        for r in results:
            meshes.setdefault(r["mesh"], (int(r["dim"]), int(r["nodes"]), int(r["elements"])))
        rows = []
        for name, (dim, nodes, elements) in meshes.items():
            print(f"dolfinx on {name} ({nodes} nodes, {elements} elements)", flush=True)
            d = run_dolfinx(mesh_dir, name, dim, nodes)
            print(f"  dolfinx| re-assembly {d['assembly']:.3f} s ({elements / d['assembly']:.3g} elements/s)")
            for problem in ("steady", "step"):
                p = d[problem]
                print(f"  dolfinx| {problem:6s} matrix {p['matrix']:.3f} s  AMG setup {p['setup']:.3f} s  "
                      f"solve {p['solve']:.3f} s  iterations {p['iterations']}  max u {p['maxu']:.6f}", flush=True)
            ours = {(r["what"], r.get("backend"), r.get("threads")): r for r in results if r["mesh"] == name}
            asm = ours.get(("assembly", None, str(args.threads))) or ours.get(("assembly", None, "1"))
            rows.append((name, "re-assembly el/s", elements / float(asm["seconds"]), elements / d["assembly"], ""))
            for problem in ("steady", "step"):
                p = d[problem]
                theirs = p["matrix"] + p["setup"] + p["solve"]
                for backend in ("amg", "cholmod", "direct", "cg"):
                    r = ours.get((problem, backend, None))
                    if r is None:
                        continue
                    mine = float(r["setup"]) + float(r["seconds"])
                    rows.append((name, f"{problem} {backend} s", mine, theirs,
                                 f"it {r['iterations']} vs {p['iterations']}; max u {float(r['maxu']):.6f} vs "
                                 f"{p['maxu']:.6f}"))
        print()
        print(f"Tessella vs dolfinx 0.5 (one process, OMP_NUM_THREADS={args.threads}); time ratio < 1 and "
              "rate ratio > 1 favour Tessella")
        print(f"{'mesh':10s} {'quantity':22s} {'tessella':>12s} {'dolfinx':>12s} {'ratio':>8s}  notes")
        for name, what, mine, theirs, note in rows:
            print(f"{name:10s} {what:22s} {mine:12.4g} {theirs:12.4g} {mine / theirs:8.3f}  {note}")
    finally:
        shutil.rmtree(mesh_dir, ignore_errors=True)


if __name__ == "__main__":
    main()
