#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# End-to-end checks of the tessella CLI: cli_cases.sh TESSELLA SOURCE_DIR CASE
# Each case runs the real executable and checks exit code, messages and files.
set -uo pipefail
tessella="$1"; src="$2"; case_name="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL [$case_name]: $*" >&2; exit 1; }

# expect_error CONFIG REGEX [ARGS...]: exit code 1, REGEX on stderr, no output directory.
expect_error() {
  local config="$1" regex="$2"; shift 2
  "$tessella" run "$config" --out "$tmp/out" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  cat "$tmp/stderr"
  [ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
  grep -Eq -- "$regex" "$tmp/stderr" || fail "stderr does not match: $regex"
  [ ! -e "$tmp/out" ] || fail "the output directory was created"
}

bad="$src/tests/apps/bad_configs"
case "$case_name" in
  run_and_info)
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/hex" --quiet >"$tmp/stdout" 2>"$tmp/stderr" \
      || fail "run failed: $(cat "$tmp/stderr")"
    [ ! -s "$tmp/stdout" ] && [ ! -s "$tmp/stderr" ] || fail "--quiet printed something"
    n=$(ls "$tmp/hex"/tissue_*.vtu | wc -l)
    [ "$n" -eq 4 ] || fail "expected 4 snapshots (steps 0, 2, 4, 5), found $n"
    [ -f "$tmp/hex/run.yaml" ] || fail "no run.yaml"
    [ "$(grep -c '<DataSet' "$tmp/hex/tissue.pvd")" -eq 4 ] || fail "the .pvd does not list 4 snapshots"
    "$tessella" info "$tmp/hex/tissue_000003.vtu" >"$tmp/info" || fail "info failed"
    cat "$tmp/info"
    grep -Eq '^cells +48$' "$tmp/info" || fail "info: expected 48 cells"
    grep -Eq '^validate +ok$' "$tmp/info" || fail "info: expected validate ok"
    # 48 regular hexagons of circumradius 1: area 48 * 3 sqrt(3) / 2 = 124.708
    grep -Eq '^total area +124\.708' "$tmp/info" || fail "info: expected total area 124.708"
    ;;
  rerun_from_record)
    "$tessella" run "$src/configs/voronoi_disk_2d.yaml" --out "$tmp/a" -q --set tissue.voronoi.count=20 \
      || fail "first run failed"
    "$tessella" run "$tmp/a/run.yaml" --out "$tmp/b" -q || fail "re-run from run.yaml failed"
    "$tessella" info "$tmp/a/tissue_000004.vtu" | grep -v '^file' >"$tmp/ia"
    "$tessella" info "$tmp/b/tissue_000004.vtu" | grep -v '^file' >"$tmp/ib"
    diff "$tmp/ia" "$tmp/ib" || fail "the re-run differs"
    ;;
  progress_and_notes)
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/p" --set tissue.dome.height=1 \
      >"$tmp/stdout" 2>"$tmp/stderr" || fail "run failed"
    cat "$tmp/stderr" "$tmp/stdout"
    grep -q 'note: .*tissue.dome is ignored: tissue.generator is hexagonal_grid' "$tmp/stderr" || fail "no note"
    grep -q 'step 5/5 (100%)' "$tmp/stderr" || fail "no final progress line"
    grep -q 'wrote 4 snapshots' "$tmp/stdout" || fail "no summary"
    ;;
  refuse_existing_run)
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/out" -q || fail "first run failed"
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/out" -q 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "a second run into the same directory was not refused"
    grep -q 'already holds a run' "$tmp/stderr" || fail "unclear refusal: $(cat "$tmp/stderr")"
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/out" -q --overwrite || fail "--overwrite failed"
    ;;
  unknown_key)
    expect_error "$bad/unknown_key.yaml" "unknown_key.yaml:4:5: tissue.voronoi.cuont: unknown key 'cuont'; did you mean 'count'\?" ;;
  wrong_type)
    expect_error "$bad/wrong_type.yaml" "wrong_type.yaml:4:12: tissue.voronoi.count: expected an integer .*got 'many'" ;;
  out_of_range)
    expect_error "$bad/out_of_range.yaml" "out_of_range.yaml:4:7: time.dt: value -0.5 is out of range; expected a number > 0" ;;
  missing_seed_file)
    expect_error "$bad/missing_seed_file.yaml" "missing_seed_file.yaml:4:16: tissue.voronoi.seed_file: file not found: 'no_such_seeds.csv'" ;;
  malformed_yaml)
    expect_error "$bad/malformed.yaml" "malformed.yaml:[0-9]+:[0-9]+: malformed YAML" ;;
  two_documents)
    expect_error "$bad/two_documents.yaml" "two_documents.yaml:4:1: a second YAML document starts here" ;;
  bad_set)
    expect_error "$src/configs/hex_grid_2d.yaml" "--set tissue.hexagonal_grid.radus=2: tissue.hexagonal_grid.radus: unknown key 'radus'; did you mean 'tissue.hexagonal_grid.radius'\?" \
      --set tissue.hexagonal_grid.radus=2 ;;
  bad_set_value)
    expect_error "$src/configs/hex_grid_2d.yaml" "--set time.end=soon: time.end: expected a number, got 'soon'" --set time.end=soon ;;
  missing_config)
    expect_error "$tmp/nowhere.yaml" "nowhere.yaml: config file not found" ;;
  empty_out)
    # --out '' is refused, not taken for runs/<config name> (run from $tmp: nothing may appear there).
    (cd "$tmp" && "$tessella" run "$src/configs/hex_grid_2d.yaml" --out '' -q >"$tmp/stdout" 2>"$tmp/stderr")
    rc=$?
    cat "$tmp/stderr"
    [ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
    grep -q "output.directory: the output directory is empty" "$tmp/stderr" || fail "unclear error"
    [ ! -e "$tmp/runs" ] || fail "runs/ was created"
    ;;
  mesh_snapshot)
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/hex" -q --set time.end=0 || fail "run failed"
    "$tessella" mesh "$tmp/hex/tissue_000000.vtu" --out "$tmp/m.vtu" --walls "$tmp/w.vtu" --size 0.4 --min-angle 25 \
      >"$tmp/stdout" 2>"$tmp/stderr" || fail "mesh failed: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    [ -s "$tmp/m.vtu" ] && [ -s "$tmp/w.vtu" ] || fail "no mesh files"
    grep -Eq '^mesh +[0-9]+ nodes, [0-9]+ triangles' "$tmp/stdout" || fail "no mesh summary"
    grep -Eq 'min_angle 25 deg, max_edge_length 0.4' "$tmp/stdout" || fail "the flags were not applied"
    # Per-cell areas agree to 1e-9: the worst difference is printed as e-1x or 0.
    grep -Eq '^cell area +worst relative difference (0|[0-9.]+e-(1[0-9]|09)) ' "$tmp/stdout" \
      || fail "per-cell areas disagree"
    # The mesh: section of a config, overridden by a flag.
    printf 'tissue: {generator: hexagonal_grid}\nmesh: {max_edge_length: 0.3, min_angle: 22}\n' >"$tmp/c.yaml"
    "$tessella" mesh "$tmp/hex/tissue_000000.vtu" --out "$tmp/m2.vtu" --config "$tmp/c.yaml" --min-angle 21 \
      >"$tmp/stdout" 2>&1 || fail "mesh --config failed: $(cat "$tmp/stdout")"
    grep -Eq 'min_angle 21 deg, max_edge_length 0.3' "$tmp/stdout" || fail "config/flag precedence: $(cat "$tmp/stdout")"
    ;;
  mesh_snapshot_3d)
    "$tessella" run "$src/configs/voronoi_box_3d.yaml" --out "$tmp/box" -q --set time.end=0 \
      --set tissue.voronoi.count=30 || fail "run failed"
    "$tessella" mesh "$tmp/box/tissue_000000.vtu" --out "$tmp/m.vtu" >"$tmp/stdout" 2>"$tmp/stderr" \
      || fail "mesh failed: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    grep -Eq '^mesh +[0-9]+ nodes, [0-9]+ tetrahedra' "$tmp/stdout" || fail "no mesh summary"
    grep -Eq '^cell volume +worst relative difference (0|[0-9.]+e-(1[0-9]|09)) ' "$tmp/stdout" \
      || fail "per-cell volumes disagree"
    grep -q 'cell_by_cell' "$tmp/stdout" || fail "the default volume method is not reported"
    # The other volume method, by flag; a method that does not exist is refused.
    "$tessella" mesh "$tmp/box/tissue_000000.vtu" --out "$tmp/m2.vtu" --volume-method whole_tissue \
      >"$tmp/stdout" 2>"$tmp/stderr" || fail "mesh --volume-method whole_tissue failed: $(cat "$tmp/stderr")"
    grep -q 'whole_tissue' "$tmp/stdout" || fail "the volume method is not reported: $(cat "$tmp/stdout")"
    grep -Eq '^cell volume +worst relative difference (0|[0-9.]+e-(1[0-9]|09)) ' "$tmp/stdout" \
      || fail "per-cell volumes disagree (whole_tissue)"
    "$tessella" mesh "$tmp/box/tissue_000000.vtu" --out "$tmp/m3.vtu" --volume-method fastest 2>"$tmp/stderr"
    [ $? -ne 0 ] || fail "--volume-method fastest was accepted"
    grep -q 'fastest' "$tmp/stderr" || fail "unclear --volume-method error: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/m3.vtu" ] || fail "an output file was left"
    ;;
  mesh_every_config)
    # Every bundled configuration's initial tissue meshes, with cell measures kept.
    for config in "$src"/configs/*.yaml; do
      name="$(basename "$config" .yaml)"
      "$tessella" run "$config" --out "$tmp/$name" -q --set time.end=0 2>"$tmp/stderr" \
        || fail "$name: run failed: $(cat "$tmp/stderr")"
      snapshot="$tmp/$name/tissue_000000.vtu"  # no bundled config renames the series
      "$tessella" mesh "$snapshot" --out "$tmp/$name.mesh.vtu" >"$tmp/stdout" 2>"$tmp/stderr" \
        || fail "$name: mesh failed: $(cat "$tmp/stderr")"
      grep -Eq 'worst relative difference (0|[0-9.]+e-(1[0-9]|09)) ' "$tmp/stdout" \
        || fail "$name: measures disagree: $(cat "$tmp/stdout")"
      echo "$name: $(grep '^mesh' "$tmp/stdout")"
    done
    ;;
  mesh_errors)
    "$tessella" mesh "$tmp/none.vtu" --out "$tmp/m.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "a missing snapshot was not an error"
    grep -q 'none.vtu' "$tmp/stderr" || fail "the error does not name the file: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/m.vtu" ] || fail "an output file was left"
    echo 'not a vtu' >"$tmp/bad.vtu"
    "$tessella" mesh "$tmp/bad.vtu" --out "$tmp/m.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "a bad snapshot was not an error"
    grep -q 'bad.vtu' "$tmp/stderr" || fail "the error does not name the file: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/m.vtu" ] || fail "an output file was left"
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/hex" -q --set time.end=0 || fail "run failed"
    "$tessella" mesh "$tmp/hex/tissue_000000.vtu" --out "$tmp/m.vtu" --min-angle 50 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "--min-angle 50 was accepted"
    grep -q 'min_angle_degrees = 50' "$tmp/stderr" || fail "unclear option error: $(cat "$tmp/stderr")"
    "$tessella" mesh "$tmp/hex/tissue_000000.vtu" --out "$tmp/no_dir/m.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "writing into a missing directory was not an error"
    [ ! -e "$tmp/no_dir" ] || fail "a directory was created"
    [ ! -e "$tmp/m.vtu" ] || fail "an output file was left"
    # Every output is checked before meshing: a --walls file into a missing directory writes no main mesh.
    "$tessella" mesh "$tmp/hex/tissue_000000.vtu" --out "$tmp/m.vtu" --walls "$tmp/no_dir/w.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "--walls into a missing directory was not an error"
    grep -q -- "--walls $tmp/no_dir/w.vtu: the directory $tmp/no_dir does not exist" "$tmp/stderr" \
      || fail "unclear --walls error: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/m.vtu" ] || fail "the main mesh was written before the walls failed"
    # A size that asks for billions of triangles is refused at once, naming the estimate, size and limit.
    start=$(date +%s)
    "$tessella" mesh "$tmp/hex/tissue_000000.vtu" --out "$tmp/m.vtu" --size 1e-6 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "--size 1e-6 was not refused"
    cat "$tmp/stderr"
    grep -Eq 'max_edge_length = 1e-06\) ask for at least [0-9.]+e\+1[0-9] triangles.*max_elements = 2e\+07' "$tmp/stderr" \
      || fail "unclear limit error: $(cat "$tmp/stderr")"
    [ $(( $(date +%s) - start )) -lt 10 ] || fail "the refusal took too long"
    [ ! -e "$tmp/m.vtu" ] || fail "an output file was left"
    # --max-elements sets the limit (0 = none).
    "$tessella" mesh "$tmp/hex/tissue_000000.vtu" --out "$tmp/m.vtu" --size 0.4 --max-elements 10 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q 'max_elements = 10;' "$tmp/stderr" || fail "--max-elements 10 was not applied"
    "$tessella" mesh "$tmp/hex/tissue_000000.vtu" --out "$tmp/m.vtu" --size 0.4 --max-elements 0 >/dev/null \
      || fail "--max-elements 0 refused a mesh"
    ;;
  snapshot_dimension)
    # A 3D snapshot restarted under a 2D config is refused before anything is written.
    "$tessella" run "$src/configs/voronoi_box_3d.yaml" --out "$tmp/box" -q --set time.end=0 \
      --set tissue.voronoi.count=20 || fail "run failed"
    expect_error "$src/configs/voronoi_growth.yaml" \
      "tissue.snapshot.file: the snapshot holds a 3D tissue, but this config describes a 2D one" \
      --set tissue.generator=snapshot --set "tissue.snapshot.file=$tmp/box/tissue_000000.vtu"
    ;;
  nonfinite_expression)
    # A velocity expression that divides by zero at t = 0.5: an error naming the expression, the vertex,
    # its position and the time, with the inversion check on or off; every snapshot written before reads back.
    for check in true false; do
      rm -rf "$tmp/out"
      "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/out" -q --set time.end=2 --set time.dt=0.25 \
        --set growth.field=expression --set growth.expression.vx='x / (t - 0.5)' \
        --set growth.check_inversion=$check >"$tmp/stdout" 2>"$tmp/stderr"
      rc=$?
      cat "$tmp/stderr"
      [ "$rc" -eq 1 ] || fail "check_inversion=$check: exit code $rc, expected 1"
      grep -q 'vx = "x / (t - 0.5)" gives' "$tmp/stderr" || fail "the expression is not named"
      grep -Eq 'not finite at vertex [0-9]+, position \(' "$tmp/stderr" || fail "the vertex is not named"
      grep -q 't = 0.5' "$tmp/stderr" || fail "the time is not named"
      grep -q 'inverted' "$tmp/stderr" && fail "reported as an inverted cell"
      for snapshot in "$tmp/out"/tissue_*.vtu; do
        "$tessella" info "$snapshot" >/dev/null 2>&1 || fail "$snapshot does not read back"
      done
    done
    ;;
  nonfinite_overflow)
    # Finite velocities whose positions overflow: refused, the snapshots stay finite.
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/out" -q --set growth.field=expression \
      --set growth.expression.vx='1e300*x*x' --set growth.check_inversion=false >"$tmp/stdout" 2>"$tmp/stderr"
    rc=$?
    cat "$tmp/stderr"
    [ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
    grep -Eq 'vx = "1e300\*x\*x" gives inf|non-finite position' "$tmp/stderr" || fail "no clear error"
    for snapshot in "$tmp/out"/tissue_*.vtu; do
      "$tessella" info "$snapshot" >/dev/null 2>&1 || fail "$snapshot does not read back"
    done
    ;;
  interrupt_sigint|interrupt_sigterm)
    # A run stopped by a signal finishes the file it writes, says what it saved and exits 128 + signal;
    # the .pvd lists complete snapshots only and no temporary is left. Several trials hit different moments.
    if [ "$case_name" = interrupt_sigint ]; then sig=INT; code=130; else sig=TERM; code=143; fi
    set -m  # background jobs of a script ignore SIGINT otherwise
    for delay in 0.3 0.7 1.1; do
      out="$tmp/run_$delay"
      "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$out" -q --set tissue.hexagonal_grid.nx=120 \
        --set tissue.hexagonal_grid.ny=120 --set time.end=100000 --set output.every=1 \
        >"$tmp/stdout" 2>"$tmp/stderr" &
      pid=$!
      for _ in $(seq 100); do [ -f "$out/tissue.pvd" ] && break; sleep 0.1; done
      [ -f "$out/tissue.pvd" ] || { kill -9 "$pid"; fail "the run wrote no series"; }
      sleep "$delay"
      kill -s "$sig" "$pid"
      for _ in $(seq 300); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
      kill -0 "$pid" 2>/dev/null && { kill -9 "$pid"; fail "the run did not stop within 30 s of SIG$sig"; }
      wait "$pid"
      rc=$?
      cat "$tmp/stderr"
      [ "$rc" -eq "$code" ] || fail "exit code $rc after SIG$sig, expected $code"
      grep -Eq "^interrupted \(SIG$sig\) after step [0-9]+/100000 .*saved [0-9]+ complete snapshots, listed in .*tissue.pvd" \
        "$tmp/stderr" || fail "no report of what was saved"
      left=$(find "$out" -name '*.tmp*')
      [ -z "$left" ] || fail "temporaries left: $left"
      listed=$(grep -c '<DataSet' "$out/tissue.pvd")
      files=$(ls "$out"/tissue_*.vtu | wc -l)
      saved=$(sed -En 's/.*saved ([0-9]+) complete snapshots.*/\1/p' "$tmp/stderr")
      [ "$listed" -eq "$files" ] && [ "$listed" -eq "$saved" ] \
        || fail "the .pvd lists $listed snapshots, the directory holds $files, the report says $saved"
      for f in $(sed -En 's/.*file="([^"]+)".*/\1/p' "$out/tissue.pvd"); do
        [ -s "$out/$f" ] || fail "$f, listed in the .pvd, is missing or empty"
      done
      "$tessella" info "$out/$f" >/dev/null 2>&1 || fail "$f, the last snapshot listed, does not read back"
    done
    ;;
  resume_interrupted)
    # A run stopped half way (killed outright in 2D, SIGTERM in 3D) and resumed with --resume ends with the
    # directory of the uninterrupted run: the same .pvd, the same stats.csv rows, every snapshot byte for
    # byte (positions, properties, random stream), and no temporary left. With transient diffusion, the
    # solver fields' state beside each snapshot and the fields series are identical too; with primordium
    # detection, primordia.csv.
    set -m
    for spec in "voronoi_growth.yaml KILL time.end=20" "box_growth_3d.yaml TERM time.end=8" \
                "morphogen_gradient_2d.yaml KILL time.end=10" "phyllotaxis_dome.yaml KILL time.end=6"; do
      read -r config sig end <<<"$spec"
      whole="$tmp/whole_${config%.yaml}"; part="$tmp/part_${config%.yaml}"
      "$tessella" run "$src/configs/$config" --out "$whole" -q --set output.every=1 --set "$end" \
        || fail "$config: the uninterrupted run failed"
      total=$(grep -c '<DataSet' "$whole/tissue.pvd")
      "$tessella" run "$src/configs/$config" --out "$part" -q --set output.every=1 --set "$end" \
        >"$tmp/stdout" 2>"$tmp/stderr" &
      pid=$!
      for _ in $(seq 600); do
        [ -f "$part/tissue.pvd" ] && [ "$(grep -c '<DataSet' "$part/tissue.pvd")" -ge $((total / 3)) ] && break
        sleep 0.02
      done
      kill -s "$sig" "$pid"
      wait "$pid"
      rc=$?
      [ "$rc" -ne 0 ] || fail "$config: the run finished before SIG$sig stopped it (make it longer)"
      listed=$(grep -c '<DataSet' "$part/tissue.pvd")
      [ "$listed" -lt "$total" ] || fail "$config: the stopped run lists all $total snapshots"
      "$tessella" run --resume "$part" >"$tmp/stdout" 2>"$tmp/stderr" || fail "$config: --resume failed: $(cat "$tmp/stderr")"
      cat "$tmp/stderr"
      grep -Eq "^resuming from .*tissue_[0-9]+\.vtu \(step [0-9]+, t = " "$tmp/stderr" || fail "$config: no resume line"
      cmp "$whole/tissue.pvd" "$part/tissue.pvd" || fail "$config: the .pvd differs"
      cmp "$whole/stats.csv" "$part/stats.csv" || fail "$config: stats.csv differs"
      if [ -e "$whole/primordia.csv" ]; then  # network.primordia: the records come back from the run state
        cmp "$whole/primordia.csv" "$part/primordia.csv" || fail "$config: primordia.csv differs"
      fi
      diff <(grep -v 'directory:' "$whole/run.yaml") <(grep -v 'directory:' "$part/run.yaml") \
        || fail "$config: run.yaml differs (beyond output.directory)"
      n=0
      for f in "$whole"/tissue_*[0-9].vtu; do
        cmp "$f" "$part/$(basename "$f")" || fail "$config: $(basename "$f") differs"
        n=$((n + 1))
      done
      [ "$n" -eq "$total" ] && [ "$(ls "$part"/tissue_*[0-9].vtu | wc -l)" -eq "$total" ] \
        || fail "$config: snapshot counts"
      # The solver fields: their state beside every snapshot, and the fields series.
      for f in "$whole"/tissue_*.fields.vtu "$whole"/fields*.pvd "$whole"/fields_*.vtu; do
        [ -e "$f" ] || continue
        cmp "$f" "$part/$(basename "$f")" || fail "$config: $(basename "$f") differs"
      done
      [ "$(ls "$whole" | wc -l)" -eq "$(ls "$part" | wc -l)" ] \
        || fail "$config: the directories hold $(ls "$whole" | wc -l) and $(ls "$part" | wc -l) files"
      if [ "$config" = morphogen_gradient_2d.yaml ]; then
        [ "$(ls "$part"/tissue_*.fields.vtu | wc -l)" -eq "$total" ] || fail "$config: not one field state per snapshot"
      fi
      left=$(find "$part" -name '*.tmp*')
      [ -z "$left" ] || fail "$config: temporaries left: $left"
      echo "$config: stopped by SIG$sig after $listed of $total snapshots, resumed: identical"
    done
    ;;
  resume_errors)
    # Clear errors, nothing written: not a directory, not a run, no complete snapshot, already finished.
    expect_resume_error() {
      local dir="$1" regex="$2"
      "$tessella" run --resume "$dir" >"$tmp/stdout" 2>"$tmp/stderr"
      local rc=$?
      cat "$tmp/stderr"
      [ "$rc" -eq 1 ] || fail "exit code $rc for --resume $dir, expected 1"
      grep -Eq -- "$regex" "$tmp/stderr" || fail "stderr does not match: $regex"
    }
    expect_resume_error "$tmp/nowhere" "^error: cannot resume '.*nowhere': no such directory$"
    mkdir "$tmp/empty"
    expect_resume_error "$tmp/empty" "cannot resume '.*empty': it is not a run directory \(no run.yaml"
    [ -z "$(ls "$tmp/empty")" ] || fail "something was written into a directory that is not a run"
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/done" -q || fail "run failed"
    cp -r "$tmp/done" "$tmp/done_copy"
    expect_resume_error "$tmp/done" "cannot resume '.*done': the run is already finished \(its last snapshot, tissue_000003.vtu, is at t = 5"
    diff -r "$tmp/done" "$tmp/done_copy" >/dev/null || fail "a finished run was changed"
    mkdir "$tmp/record_only" && cp "$tmp/done/run.yaml" "$tmp/record_only/"
    expect_resume_error "$tmp/record_only" "cannot resume '.*record_only': it has no complete snapshot \(no tissue.pvd\)"
    cp -r "$tmp/done" "$tmp/broken"
    for f in "$tmp/broken"/tissue_*.vtu; do printf 'damaged' >"$f"; done
    expect_resume_error "$tmp/broken" "none of the 4 snapshots listed in tissue.pvd is complete"
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --resume "$tmp/done" >"$tmp/stdout" 2>"$tmp/stderr"
    [ $? -ne 0 ] || fail "a config and --resume together were accepted"
    grep -q 'excludes' "$tmp/stderr" || fail "unclear refusal of a config with --resume: $(cat "$tmp/stderr")"
    ;;
  overwrite_removes_temporaries)
    # What an interrupted run of an older version left behind goes with --overwrite.
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/out" -q || fail "first run failed"
    : >"$tmp/out/tissue_000007.vtu.tmp-123-4"; : >"$tmp/out/tissue.pvd.tmp-123-5"; : >"$tmp/out/run.yaml.tmp"
    : >"$tmp/out/keep.txt"
    # A previous run's primordia table goes too, though this run records none.
    printf 'id,time\n0,1\n' >"$tmp/out/primordia.csv"; : >"$tmp/out/primordia.csv.tmp"
    # And its PIN walls files (network.pin), this run writing none.
    : >"$tmp/out/tissue_000009.pin.vtu"; : >"$tmp/out/tissue_000010.pin.vtu.tmp-123-6"
    # And its mechanics walls files and the walls files' series.
    : >"$tmp/out/tissue_000009.walls.vtu"; : >"$tmp/out/tissue.walls.pvd"; : >"$tmp/out/tissue.pin.pvd"
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/out" -q --overwrite || fail "--overwrite failed"
    left=$(find "$tmp/out" -name '*.tmp*')
    [ -z "$left" ] || fail "temporaries left: $left"
    [ -f "$tmp/out/keep.txt" ] || fail "a file of the user's was removed"
    [ ! -e "$tmp/out/primordia.csv" ] || fail "the previous run's primordia.csv was left"
    [ ! -e "$tmp/out/tissue_000009.pin.vtu" ] || fail "the previous run's PIN walls file was left"
    for f in tissue_000009.walls.vtu tissue.walls.pvd tissue.pin.pvd; do
      [ ! -e "$tmp/out/$f" ] || fail "the previous run's $f was left"
    done
    ;;
  disk_full)
    # A full disk: the error names the file and says "No space left on device", without VTK's dump,
    # and no temporary is left. Needs a small tmpfs (root, or a mount namespace).
    mkdir -p "$tmp/full"
    if ! mount -t tmpfs -o size=64k tmpfs "$tmp/full" 2>/dev/null; then
      echo "SKIPPED [$case_name]: cannot mount a small tmpfs here (needs root)"; exit 77
    fi
    trap 'umount "$tmp/full"; rm -rf "$tmp"' EXIT
    # A snapshot larger than the disk.
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/full/a" -q --set tissue.hexagonal_grid.nx=60 \
      --set tissue.hexagonal_grid.ny=60 --set output.compression=none >"$tmp/stdout" 2>"$tmp/stderr"
    rc=$?
    cat "$tmp/stderr"
    [ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
    grep -q "cannot write '$tmp/full/a/tissue_000000.vtu': No space left on device" "$tmp/stderr" \
      || fail "the error does not give the file and the reason"
    grep -Eq 'vtkInformation|Debug: Off|0x[0-9a-f]{6}' "$tmp/stderr" && fail "VTK's internal dump is in the message"
    [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "more than one line printed"
    left=$(find "$tmp/full" -name '*.tmp*')
    [ -z "$left" ] || fail "temporaries left: $left"
    # The disk fills up before run.yaml.
    rm -rf "$tmp/full/a"
    mkdir "$tmp/full/b"
    dd if=/dev/zero of="$tmp/full/filler" bs=1k count=100 2>/dev/null
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/full/b" -q >"$tmp/stdout" 2>"$tmp/stderr"
    rc=$?
    cat "$tmp/stderr"
    [ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
    grep -q "cannot write '$tmp/full/b/run.yaml': No space left on device" "$tmp/stderr" \
      || fail "the run.yaml error does not give the file and the reason"
    [ -z "$(ls -A "$tmp/full/b")" ] || fail "files left: $(ls -A "$tmp/full/b")"
    ;;
  long_csv_line)
    # A seed file with a 20 MB line of binary bytes: the error quotes a short, escaped excerpt.
    mkdir -p "$tmp/cfg"
    { printf 'x,y\n1,2\n3,4,'; head -c 20000000 /dev/zero | tr '\0' '\001'; printf '\n'; } >"$tmp/cfg/seeds.csv"
    printf 'tissue:\n  generator: voronoi\n  voronoi:\n    seed_file: seeds.csv\n' >"$tmp/cfg/c.yaml"
    "$tessella" run "$tmp/cfg/c.yaml" --out "$tmp/out" >"$tmp/stdout" 2>"$tmp/stderr"
    rc=$?
    [ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
    bytes=$(wc -c <"$tmp/stderr")
    head -c 600 "$tmp/stderr"; echo
    [ "$bytes" -lt 1000 ] || fail "the error is $bytes bytes long"
    grep -q 'seeds.csv:3' "$tmp/stderr" || fail "the line is not named"
    grep -Fq '\x01\x01' "$tmp/stderr" || fail "the bytes are not escaped"
    grep -Eq '\.\.\. \([0-9]+ more bytes\)' "$tmp/stderr" || fail "the cut is not said"
    LC_ALL=C grep -q "$(printf '\001')" "$tmp/stderr" && fail "a raw control byte was printed"
    ;;
  vtk_messages)
    # Read errors VTK reports (some through objects Tessella cannot watch) come as one line naming the
    # file, without VTK's object dumps, addresses or coloured log lines.
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/hex" -q --set time.end=0 || fail "run failed"
    snapshot="$tmp/hex/tissue_000000.vtu"
    for edit in 's/byte_order="LittleEndian"/byte_order="Middle"/' 's/header_type="UInt64"/header_type="UInt16"/' \
                's/NumberOfComponents="3"/NumberOfComponents="x"/'; do
      LC_ALL=C sed "$edit" "$snapshot" >"$tmp/bad.vtu"
      "$tessella" info "$tmp/bad.vtu" >"$tmp/stdout" 2>"$tmp/stderr"
      rc=$?
      cat "$tmp/stderr"
      [ "$rc" -eq 1 ] || fail "$edit: exit code $rc, expected 1"
      [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "$edit: more than one line printed"
      grep -q "^error: cannot read '$tmp/bad.vtu': " "$tmp/stderr" || fail "$edit: the file is not named"
      grep -Eq 'vtkInformation|Debug: Off|\(0x[0-9a-f]+\)' "$tmp/stderr" && fail "$edit: VTK's dump is in the message"
      grep -q "$(printf '\033')" "$tmp/stderr" && fail "$edit: a coloured log line was printed"
    done
    ;;
  corrupted_snapshot)
    # A damaged snapshot is one clear error line and exit code 1 for info, mesh
    # and a restart: a type name VTK's reader crashes on (SIGSEGV), a header
    # type it crashes on too (SIGSEGV here, SIGFPE in an LZ4 file), a flipped bit
    # in a coordinate.
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/hex" -q --set time.end=0 \
      --set output.compression=none || fail "run failed"
    good="$tmp/hex/tissue_000000.vtu"
    sed 's/type="String"/type="Xtring"/' "$good" >"$tmp/xtring.vtu"
    sed 's/header_type="UInt64"/header_type="UInt32"/' "$good" >"$tmp/uint32.vtu"
    cmp -s "$good" "$tmp/xtring.vtu" && fail "no type=\"String\" to damage"
    cmp -s "$good" "$tmp/uint32.vtu" && fail "no header_type=\"UInt64\" to damage"
    # The sign of the first point's x coordinate flips: the file still
    # decodes and forms a tissue, only the checksum tells.
    cp "$good" "$tmp/flipped.vtu"
    start=$(grep -obUa '<AppendedData encoding="raw">' "$good" | cut -d: -f1)
    offset=$(grep -Eao 'Name="Points" NumberOfComponents="3" format="appended"[^>]*offset="[0-9]+"' "$good" \
      | sed 's/.*offset="\([0-9]*\)"/\1/')
    [ -n "$start" ] && [ -n "$offset" ] || fail "cannot locate the points in the snapshot"
    # Data start after '<AppendedData encoding="raw">', a newline, spaces and '_';
    # the array starts with an 8-byte size header; the last byte of x is the sign.
    data=$(( $(grep -obUa '_' "$good" | awk -F: -v s="$start" '$1 > s { print $1; exit }') + 1 ))
    printf '\x80' | dd of="$tmp/flipped.vtu" bs=1 seek=$(( data + offset + 8 + 7 )) conv=notrunc status=none
    cmp -s "$good" "$tmp/flipped.vtu" && fail "the flip changed nothing"
    for damaged in xtring uint32 flipped; do
      file="$tmp/$damaged.vtu"
      for command in info mesh run; do
        case "$command" in
          info) "$tessella" info "$file" >"$tmp/stdout" 2>"$tmp/stderr" ;;
          mesh) "$tessella" mesh "$file" --out "$tmp/m.vtu" >"$tmp/stdout" 2>"$tmp/stderr" ;;
          run) "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/restart" -q \
                 --set tissue.generator=snapshot --set tissue.snapshot.file="$file" >"$tmp/stdout" 2>"$tmp/stderr" ;;
        esac
        rc=$?
        echo "$damaged/$command: rc $rc: $(cat "$tmp/stderr")"
        [ "$rc" -eq 1 ] || fail "$damaged/$command: exit code $rc, expected 1"
        [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "$damaged/$command: not one error line: $(cat "$tmp/stderr")"
        grep -q "$damaged.vtu" "$tmp/stderr" || fail "$damaged/$command: the error does not name the file"
        grep -q "corrupted" "$tmp/stderr" || fail "$damaged/$command: the error does not say the file is corrupted"
        [ ! -e "$tmp/m.vtu" ] && [ ! -e "$tmp/restart" ] || fail "$damaged/$command: output was written"
      done
    done
    grep -q 'crashed (signal' <("$tessella" info "$tmp/xtring.vtu" 2>&1) || fail "the crash is not reported as such"
    grep -q "does not match its checksum" <("$tessella" info "$tmp/flipped.vtu" 2>&1) || fail "no checksum error"
    ;;
  import_meristem)
    mgx="$src/tests/data/mgx_meristem_cropped/mesh_meristem_cropped_T0.ply"
    "$tessella" import "$mgx" --out "$tmp/t.vtu" >"$tmp/stdout" 2>"$tmp/stderr" \
      || fail "import failed: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    [ -s "$tmp/t.vtu" ] || fail "no snapshot written"
    grep -Eq '^format +morphographx \(1506 vertices, 2704 faces in the file\)$' "$tmp/stdout" || fail "no format line"
    grep -Eq '^cells +128$' "$tmp/stdout" || fail "expected 128 cells"
    grep -Eq '^tissue +2D, surface' "$tmp/stdout" || fail "expected a 2D surface tissue"
    grep -Eq '^walls +[0-9]+ \([0-9]+ cells touch the boundary\)$' "$tmp/stdout" || fail "no walls line"
    grep -Eq '^cell area +min [0-9.]+ ' "$tmp/stdout" || fail "no area range"
    grep -Eq '^repairs +0$' "$tmp/stdout" || fail "expected no repair"
    grep -Eq '^validate +ok$' "$tmp/stdout" || fail "expected validate ok"
    # The snapshot reads back with the labels.
    "$tessella" info "$tmp/t.vtu" >"$tmp/info" || fail "info failed"
    grep -Eq '^cells +128$' "$tmp/info" || fail "info: expected 128 cells"
    # Options: scale 2 multiplies areas by 4; simplify removes wall vertices.
    "$tessella" import "$mgx" --out "$tmp/s.vtu" --format morphographx --scale 2 --simplify 0.3 --repair \
      >"$tmp/stdout2" 2>"$tmp/stderr" || fail "import with options failed: $(cat "$tmp/stderr")"
    grep -Eq '^simplify +[0-9]+ wall vertices removed$' "$tmp/stdout2" || fail "no simplify line: $(cat "$tmp/stdout2")"
    a1=$(sed -n 's/^total area *//p' "$tmp/stdout"); a2=$(sed -n 's/^total area *//p' "$tmp/stdout2")
    awk -v a="$a1" -v b="$a2" 'BEGIN { r = b / (4 * a); exit !(r > 0.98 && r < 1.02) }' \
      || fail "scale 2 did not multiply the area by about 4 ($a1 -> $a2)"
    ;;
  export_cell_complex)
    # A 3D snapshot out as cell-complex PLY and back in: the same cells and total volume.
    "$tessella" run "$src/configs/voronoi_box_3d.yaml" --out "$tmp/box" -q --set time.end=0 \
      --set tissue.voronoi.count=30 || fail "run failed"
    "$tessella" export "$tmp/box/tissue_000000.vtu" --out "$tmp/box.ply" --binary >"$tmp/stdout" 2>"$tmp/stderr" \
      || fail "export failed: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    grep -Eq '^wrote +.*box.ply \(cell-complex PLY, binary: [0-9]+ vertices, [0-9]+ edges, [0-9]+ faces, 30 volumes; ' \
      "$tmp/stdout" || fail "no export summary"
    "$tessella" import "$tmp/box.ply" --out "$tmp/back.vtu" >"$tmp/import" 2>"$tmp/stderr" \
      || fail "import failed: $(cat "$tmp/stderr")"
    cat "$tmp/import"
    grep -Eq '^format +cell_complex ' "$tmp/import" || fail "not read as cell_complex"
    grep -Eq '^note +layout: closed volumes, a 3D tissue' "$tmp/import" || fail "the summary does not say 3D"
    grep -Eq '^cells +30$' "$tmp/import" || fail "expected 30 cells"
    "$tessella" info "$tmp/box/tissue_000000.vtu" >"$tmp/info"
    [ "$(sed -n 's/^total volume *//p' "$tmp/info")" = "$(sed -n 's/^total volume *//p' "$tmp/import")" ] \
      || fail "the total volume changed"
    # A cell that is not closed: an error naming the volume, nothing written.
    "$tessella" export "$tmp/box/tissue_000000.vtu" --out "$tmp/ascii.ply" >/dev/null || fail "ASCII export failed"
    # Drop the first face of the last volume (its list length goes down by one).
    awk '{ lines[NR] = $0 } END { n = split(lines[NR], f, " "); out = f[1] - 1;
         for (i = 3; i <= n; ++i) out = out " " f[i]; lines[NR] = out;
         for (i = 1; i <= NR; ++i) print lines[i] }' "$tmp/ascii.ply" >"$tmp/open.ply"
    "$tessella" import "$tmp/open.ply" --out "$tmp/open.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "an open cell was not an error"
    grep -Eq "open.ply' volume 29 \(label [0-9]+\): an open patch, but volume 0 \(label [0-9]+\) is a closed surface" \
      "$tmp/stderr" || fail "unclear error: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/open.vtu" ] || fail "an output file was left"
    ;;
  import_labelled_mesh)
    # tessella mesh's tetrahedra (cell_id per element) back into a 3D tissue: same cells, same volumes.
    "$tessella" run "$src/configs/voronoi_box_3d.yaml" --out "$tmp/box" -q --set time.end=0 \
      --set tissue.voronoi.count=12 || fail "run failed"
    "$tessella" mesh "$tmp/box/tissue_000000.vtu" --out "$tmp/mesh.vtu" >/dev/null || fail "mesh failed"
    "$tessella" import "$tmp/mesh.vtu" --out "$tmp/back.vtu" >"$tmp/import" 2>"$tmp/stderr" \
      || fail "import failed: $(cat "$tmp/stderr")"
    cat "$tmp/import"
    grep -Eq '^format +labelled_vtu \([0-9]+ vertices, [0-9]+ tetrahedra in the file\)$' "$tmp/import" \
      || fail "no format line"
    grep -Eq '^note +layout: closed cells, a 3D tissue' "$tmp/import" || fail "the summary does not say 3D"
    grep -Eq '^cells +12$' "$tmp/import" || fail "expected 12 cells"
    grep -Eq '^validate +ok$' "$tmp/import" || fail "expected validate ok"
    "$tessella" info "$tmp/box/tissue_000000.vtu" >"$tmp/info"
    for key in 'total volume' 'cell volume'; do
      [ "$(grep "^$key" "$tmp/info")" = "$(grep "^$key" "$tmp/import")" ] || fail "$key changed"
    done
    ;;
  import_labelled_faces)
    # labelled_mesh: two unit squares as labelled triangles, in OBJ (g groups) and in PLY with a label
    # property of another name, read with --label-array; each square a cell of area 1 (4 with --scale 2).
    printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\ng 5\nf 1 2 5\nf 1 5 4\ng 2\nf 2 3 6\nf 2 6 5\n' \
      >"$tmp/squares.obj"
    "$tessella" import "$tmp/squares.obj" --out "$tmp/obj.vtu" >"$tmp/import" 2>"$tmp/stderr" \
      || fail "OBJ import failed: $(cat "$tmp/stderr")"
    cat "$tmp/import"
    grep -Eq '^format +labelled_mesh \(6 vertices, 4 faces in the file\)$' "$tmp/import" || fail "no format line"
    grep -Eq '^cells +2$' "$tmp/import" || fail "expected 2 cells"
    grep -Eq '^total area +2$' "$tmp/import" || fail "expected total area 2"
    grep -Eq '^validate +ok$' "$tmp/import" || fail "expected validate ok"
    [ -f "$tmp/obj.vtu" ] || fail "no snapshot written"
    { printf 'ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n'
      printf 'element face 4\nproperty list uchar int vertex_indices\nproperty int segment\nend_header\n'
      printf '0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n3 0 1 4 5\n3 0 4 3 5\n3 1 2 5 2\n3 1 5 4 2\n'; } >"$tmp/seg.ply"
    "$tessella" import "$tmp/seg.ply" --out "$tmp/ply.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "a PLY without a known label property was imported"
    grep -q 'label-array' "$tmp/stderr" || fail "the error does not point at --label-array: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/ply.vtu" ] || fail "an output file was left"
    "$tessella" import "$tmp/seg.ply" --out "$tmp/ply.vtu" --label-array segment --scale 2 >"$tmp/import2" \
      2>"$tmp/stderr" || fail "PLY import with --label-array failed: $(cat "$tmp/stderr")"
    grep -Eq '^total area +8$' "$tmp/import2" || fail "expected total area 8: $(cat "$tmp/import2")"
    grep -q "face property 'segment'" "$tmp/import2" || fail "the label source is not named"
    "$tessella" import "$tmp/seg.ply" --out "$tmp/x.vtu" --label-array nope --format labelled_mesh 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "a missing label array was accepted"
    grep -q "no cell label property 'nope'; it has vertex_indices, segment" "$tmp/stderr" \
      || fail "unclear error: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/x.vtu" ] || fail "an output file was left"
    ;;
  import_label_image)
    # A discrete Voronoi label image (nearest of 30 seeds, labels 2..31) written as TIFF by Pillow.
    /usr/bin/python3 - "$tmp" <<'PY' || fail "could not write the images"
import sys
import numpy as np
from PIL import Image
rng = np.random.default_rng(3)
seeds = rng.uniform(0, 256, size=(30, 2))
y, x = np.mgrid[0:256, 0:256] + 0.5
d = (x[..., None] - seeds[:, 0]) ** 2 + (y[..., None] - seeds[:, 1]) ** 2
labels = (np.argmin(d, axis=2) + 2).astype(np.uint16)
Image.fromarray(labels).save(sys.argv[1] + "/cells.tif")
split = labels.copy()
split[0:3, 0:3] = labels[128, 128]  # a second piece of the label at the centre
Image.fromarray(split).save(sys.argv[1] + "/split.tif")
Image.fromarray(labels.astype(np.float32)).save(sys.argv[1] + "/float.tif")
print(len(np.unique(labels)), int(labels[128, 128]), file=open(sys.argv[1] + "/facts", "w"))
PY
    read -r ncells centre <"$tmp/facts"
    "$tessella" import "$tmp/cells.tif" --out "$tmp/t.vtu" --voxel-size 0.5,0.5 --simplify 1 >"$tmp/import" \
      2>"$tmp/stderr" || fail "import failed: $(cat "$tmp/stderr")"
    cat "$tmp/import"
    grep -Eq '^format +label_image \(0 vertices, 65536 pixels in the file\)$' "$tmp/import" || fail "no format line"
    grep -Eq "^cells +$ncells\$" "$tmp/import" || fail "expected $ncells cells"
    # Every pixel is a cell's: 256 x 256 pixels of 0.5 x 0.5.
    grep -Eq '^total area +16384$' "$tmp/import" || fail "expected total area 16384"
    grep -Eq '^validate +ok$' "$tmp/import" || fail "expected validate ok"
    [ -f "$tmp/t.vtu" ] || fail "no snapshot written"
    # The same through the YAML generator.
    cat >"$tmp/from_image.yaml" <<YAML
tissue:
  generator: import
  import:
    file: cells.tif
    voxel_size: [0.5, 0.5]
    simplify: 1.0
time:
  start: 0.0
  end: 0.0
  dt: 1.0
YAML
    "$tessella" run "$tmp/from_image.yaml" --out "$tmp/run" -q || fail "run from the image failed"
    "$tessella" info "$tmp/run/tissue_000000.vtu" >"$tmp/info" || fail "info failed"
    for key in cells 'total area' 'cell area'; do
      [ "$(grep "^$key" "$tmp/info")" = "$(grep "^$key" "$tmp/import")" ] || fail "$key differs from tessella import"
    done
    # Errors: exit 1, the file, label and value named, nothing written.
    "$tessella" import "$tmp/split.tif" --out "$tmp/s.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "a split label was not an error"
    grep -q "split.tif': label $centre is made of 2 disconnected pieces" "$tmp/stderr" \
      || fail "unclear error: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/s.vtu" ] || fail "an output file was left"
    "$tessella" import "$tmp/split.tif" --out "$tmp/s.vtu" --keep-pieces >/dev/null || fail "--keep-pieces failed"
    "$tessella" import "$tmp/float.tif" --out "$tmp/f.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q "float.tif' holds float values" "$tmp/stderr" || fail "float image: $(cat "$tmp/stderr")"
    "$tessella" import "$tmp/cells.tif" --out "$tmp/z.vtu" --voxel-size 0,1 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q "voxel_size x = 0 must be a positive" "$tmp/stderr" \
      || fail "zero voxel size: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/f.vtu" ] && [ ! -e "$tmp/z.vtu" ] || fail "an output file was left"
    ;;
  same_on_any_thread_count)
    # A run's files do not depend on the number of OpenMP threads (README): growth and division,
    # a cell network, turgor mechanics, a 3D tissue, a reaction-diffusion field; 1 thread against 2.
    for spec in voronoi_growth:4 auxin_network_2d:10 turgor_tissue_2d:0.5 box_growth_3d:1 activator_inhibitor_2d:1; do
      name=${spec%%:*}
      for threads in 1 2; do
        OMP_NUM_THREADS=$threads "$tessella" run "$src/configs/$name.yaml" --out "$tmp/$name-$threads" -q \
          --set time.end=${spec#*:} 2>"$tmp/stderr" || fail "$name on $threads threads: $(cat "$tmp/stderr")"
      done
      [ "$(ls "$tmp/$name-1" | wc -l)" -gt 3 ] || fail "$name wrote too little: $(ls "$tmp/$name-1")"
      # run.yaml names its own output directory; everything else must match byte for byte.
      diff -r -x run.yaml "$tmp/$name-1" "$tmp/$name-2" >"$tmp/diff" &&
        diff <(grep -v "directory:" "$tmp/$name-1/run.yaml") <(grep -v "directory:" "$tmp/$name-2/run.yaml") >>"$tmp/diff" ||
        fail "$name differs on 1 and 2 threads: $(head -5 "$tmp/diff")"
    done
    ;;
  render_run)
    "$tessella" run "$src/configs/hex_grid_2d.yaml" --out "$tmp/hex" -q || fail "run failed"
    "$tessella" render "$tmp/hex" --property size --size 320x240 --no-movie >"$tmp/stdout" 2>"$tmp/stderr" \
      || fail "render failed: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    grep -q "wrote        4 frames to $tmp/hex/frames" "$tmp/stdout" || fail "expected 4 frames in RUN_DIR/frames"
    for f in "$tmp/hex/frames"/frame_00000[0-3].png; do
      # A PNG's IHDR holds width and height as big-endian 32-bit integers at bytes 16..23.
      size=$(od -An -tu1 -j16 -N8 "$f" | awk '{print $3*256+$4 "x" $7*256+$8}')
      [ "$size" = "320x240" ] || fail "$f is $size, expected 320x240"
    done
    "$tessella" render "$tmp/hex/tissue_000000.vtu" --out "$tmp/one" >/dev/null || fail "render of one snapshot failed"
    [ -f "$tmp/one/frame_000000.png" ] || fail "no frame for a single snapshot"
    "$tessella" render "$tmp/hex" --property auxin --out "$tmp/bad" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "an unknown property was not refused"
    grep -q "no cell property 'auxin' (scalar cell properties: size, lineage_id" "$tmp/stderr" || fail "unclear: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/bad" ] || fail "frames directory created for a refused render"
    "$tessella" render "$tmp/nothing" 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q "no such file or directory" "$tmp/stderr" || fail "missing source: $(cat "$tmp/stderr")"
    ;;
  sweep_snakemake)
    command -v snakemake >/dev/null || fail "snakemake is not installed (scripts/install-deps.sh installs it)"
    "$tessella" sweep "$src/configs/voronoi_growth.yaml" --vary division.rule=main_axis,shortest_wall \
      --vary growth.uniform.rate=0.05,0.1 --replicates 2 --set time.end=1 --set tissue.voronoi.count=12 \
      --out "$tmp/sweep" >"$tmp/stdout" 2>"$tmp/stderr" || fail "sweep failed: $(cat "$tmp/stderr")"
    grep -q "wrote        8 run configs" "$tmp/stdout" || fail "expected 8 runs: $(cat "$tmp/stdout")"
    # Each run gets one OpenMP thread, or what --set-threads gives it (the dry run prints the commands).
    (cd "$tmp/sweep" && snakemake -n -p -j 2 >"$tmp/dry1.log" 2>&1 &&
      snakemake -n -p -c 4 --set-threads run=3 >"$tmp/dry3.log" 2>&1) || fail "dry run failed: $(tail "$tmp/dry1.log")"
    [ "$(grep -c 'OMP_NUM_THREADS=1 ' "$tmp/dry1.log")" -eq 8 ] && grep -q 'OMP_NUM_THREADS=3 ' "$tmp/dry3.log" \
      && ! grep -q 'OMP_NUM_THREADS=1 ' "$tmp/dry3.log" || fail "threads per run: $(grep -m2 OMP "$tmp/dry1.log")"
    (cd "$tmp/sweep" && snakemake -j 2 >"$tmp/sm.log" 2>&1) || fail "snakemake failed: $(tail -20 "$tmp/sm.log")"
    csv="$tmp/sweep/sweep.csv"
    [ "$(head -1 "$csv" | cut -d, -f1-7)" = "run,replicate,rng_seed,division.rule,growth.uniform.rate,time,cells" ] \
      || fail "sweep.csv header: $(head -1 "$csv")"
    [ "$(wc -l <"$csv")" -eq 9 ] || fail "sweep.csv should hold 8 runs"
    # Replicates take seeds 5 and 6 (the config's rng_seed 5, then 5 + 1), the same for every combination;
    # every run reached time.end = 1 and the faster growth gives the larger total area.
    awk -F, 'NR > 1 && ($3 != 5 + $2 || $6 != 1) { exit 1 }' "$csv" || fail "seeds or end times wrong: $(cat "$csv")"
    awk -F, 'NR > 1 { a[$5] += $9; n[$5]++ } END { exit !(a["0.1"] / n["0.1"] > a["0.05"] / n["0.05"]) }' "$csv" \
      || fail "growth rate does not show in the area: $(cat "$csv")"
    # Each run's own config carries its values; rerunning does nothing; a lost run is redone alone.
    grep -q "rule: shortest_wall" "$tmp/sweep/configs/run_0007.yaml" || fail "run_0007's config lacks its rule"
    # Captured first: grep -q under pipefail could end snakemake with SIGPIPE.
    (cd "$tmp/sweep" && snakemake -j 2 >"$tmp/sm_rerun.log" 2>&1) || fail "rerun failed"
    grep -q "Nothing to be done" "$tmp/sm_rerun.log" || fail "a rerun did work again"
    rm "$tmp/sweep/sweep.csv" "$tmp/sweep/runs/run_0003/finished"
    (cd "$tmp/sweep" && snakemake -j 2 >"$tmp/sm2.log" 2>&1) || fail "resumed snakemake failed"
    [ "$(grep -c 'wildcards: run=' "$tmp/sm2.log")" -eq 1 ] || fail "resuming reran more than the lost run"
    # Refusals: an inactive key, a malformed --vary, an existing sweep.
    "$tessella" sweep "$src/configs/hex_grid_2d.yaml" --vary growth.uniform.rate=1,2 --out "$tmp/s2" 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q "ignores this key" "$tmp/stderr" && [ ! -e "$tmp/s2" ] || fail "inactive key: $(cat "$tmp/stderr")"
    "$tessella" sweep "$src/configs/voronoi_growth.yaml" --vary division.size --out "$tmp/s3" 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q "no '='" "$tmp/stderr" || fail "malformed --vary: $(cat "$tmp/stderr")"
    "$tessella" sweep "$src/configs/voronoi_growth.yaml" --vary division.mean=-1,2 --out "$tmp/s4" 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q "division.mean" "$tmp/stderr" && [ ! -e "$tmp/s4" ] || fail "bad value: $(cat "$tmp/stderr")"
    "$tessella" sweep "$src/configs/voronoi_growth.yaml" --vary division.mean=1,2 --out "$tmp/sweep" 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q "already holds a sweep" "$tmp/stderr" || fail "existing sweep: $(cat "$tmp/stderr")"
    ;;
  report_in_browser)
    command -v chromium >/dev/null || fail "chromium is not installed (scripts/install-deps.sh installs it)"
    "$tessella" run "$src/configs/voronoi_growth.yaml" --out "$tmp/run" -q --set time.end=2 \
      --set tissue.voronoi.count=20 || fail "run failed"
    "$tessella" report "$tmp/run" >"$tmp/stdout" 2>"$tmp/stderr" || fail "report failed: $(cat "$tmp/stderr")"
    cat "$tmp/stdout"
    [ -s "$tmp/run/report.html" ] || fail "no report.html"
    # cells.csv holds every cell of every snapshot: as many rows as stats.csv counts cells.
    cells=$(awk -F, 'NR > 1 { n += $2 } END { print n }' "$tmp/run/stats.csv")
    [ "$(($(wc -l <"$tmp/run/report/cells.csv") - 1))" -eq "$cells" ] || fail "cells.csv rows != $cells"
    # Each division seen is one counted in stats.csv (a sister that divided again hides one).
    divisions=$(awk -F, 'NR > 1 { n += $3 } END { print n }' "$tmp/run/stats.csv")
    seen=$(($(wc -l <"$tmp/run/report/divisions.csv") - 1))
    [ "$seen" -gt 0 ] && [ "$seen" -le "$divisions" ] || fail "divisions seen $seen, counted $divisions"
    # In a real browser: every image of the page loads, and the page is not blank.
    chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=10000 --dump-dom \
      "file://$tmp/run/report.html" >"$tmp/dom.html" 2>"$tmp/chromium.log" || fail "chromium failed: $(tail "$tmp/chromium.log")"
    loaded=$(grep -o 'data-images-loaded="[0-9]*/[0-9]*"' "$tmp/dom.html") || fail "the page's load handler did not run"
    echo "$loaded"
    images=$(grep -c '<img ' "$tmp/run/report.html")
    [ "$loaded" = "data-images-loaded=\"$images/$images\"" ] || fail "not every image loaded: $loaded of $images"
    chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --virtual-time-budget=10000 --window-size=1000,1400 \
      --screenshot="$tmp/page.png" "file://$tmp/run/report.html" >/dev/null 2>&1 || fail "no screenshot"
    /usr/bin/python3 - "$tmp/page.png" <<'PY' || fail "screenshot check failed"
import sys
import matplotlib.image as mpimg
img = mpimg.imread(sys.argv[1])
assert img.shape[:2] == (1400, 1000), img.shape
rgb = img[:, :, :3]
ink = (rgb.min(axis=2) < 0.9).mean()
colour = ((rgb.max(axis=2) - rgb.min(axis=2)) > 0.2).mean()  # the plots' coloured marks, not black text
print(f"screenshot 1000x1400: {ink:.1%} of the pixels not white, {colour:.2%} coloured")
assert ink > 0.01 and colour > 0.002, "the page looks blank or shows no plot"
PY
    "$tessella" report "$tmp" 2>"$tmp/stderr"
    [ $? -eq 1 ] && grep -q "is not a run directory written by tessella run: it has no tissue.pvd" "$tmp/stderr" \
      || fail "a non-run directory: $(cat "$tmp/stderr")"
    ;;
  import_errors)
    # A malformed file: exit 1, an error naming the file and line, no output file.
    head -c 60000 "$src/tests/data/mgx_meristem_cropped/mesh_meristem_cropped_T0.ply" >"$tmp/cut.ply"
    "$tessella" import "$tmp/cut.ply" --out "$tmp/t.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "a truncated file was not an error"
    cat "$tmp/stderr"
    grep -Eq "cut.ply' (is truncated|line [0-9]+)" "$tmp/stderr" || fail "unclear error: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/t.vtu" ] || fail "an output file was left"
    # A face index out of range names the face and the cell label.
    awk 'NR == 2000 { $3 = 99999 } { print }' "$src/tests/data/mgx_meristem_cropped/mesh_meristem_cropped_T0.ply" \
      >"$tmp/bad.ply"
    "$tessella" import "$tmp/bad.ply" --out "$tmp/t.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "an out-of-range index was not an error"
    grep -Eq "bad.ply' face 477 \(cell label [0-9]+\): vertex index 99999 is out of range" "$tmp/stderr" \
      || fail "unclear error: $(cat "$tmp/stderr")"
    [ ! -e "$tmp/t.vtu" ] || fail "an output file was left"
    # A PLY of another layout, an unknown extension, an unknown format.
    printf 'ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nend_header\n' >"$tmp/plain.ply"
    "$tessella" import "$tmp/plain.ply" --out "$tmp/t.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "an unknown PLY layout was not an error"
    grep -q 'none of the supported formats' "$tmp/stderr" && grep -q 'morphographx (.ply)' "$tmp/stderr" \
      || fail "the error does not list the formats: $(cat "$tmp/stderr")"
    "$tessella" import "$tmp/plain.xyz" --out "$tmp/t.vtu" 2>"$tmp/stderr"
    [ $? -eq 1 ] || fail "an unknown extension was not an error"
    "$tessella" import "$tmp/plain.ply" --out "$tmp/t.vtu" --format nope 2>"$tmp/stderr"
    [ $? -ne 0 ] || fail "an unknown --format was accepted"
    [ ! -e "$tmp/t.vtu" ] || fail "an output file was left"
    ;;
  *) fail "unknown case" ;;
esac
echo "ok [$case_name]"
