#!/usr/bin/env bash
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
  bad_set)
    expect_error "$src/configs/hex_grid_2d.yaml" "--set tissue.hexagonal_grid.radus=2: tissue.hexagonal_grid.radus: unknown key 'radus'; did you mean 'tissue.hexagonal_grid.radius'\?" \
      --set tissue.hexagonal_grid.radus=2 ;;
  bad_set_value)
    expect_error "$src/configs/hex_grid_2d.yaml" "--set time.end=soon: time.end: expected a number, got 'soon'" --set time.end=soon ;;
  missing_config)
    expect_error "$tmp/nowhere.yaml" "nowhere.yaml: config file not found" ;;
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
    # [needs-robust-geometry] Real cells that are not star-shaped from their
    # vertex mean make the mesher refuse the tissue ("cell 14 folds over") until
    # the robust geometry of issue 14 part 1 lands; remove the name then.
    needs_robust_geometry=" real_meristem "
    for config in "$src"/configs/*.yaml; do
      name="$(basename "$config" .yaml)"
      case "$needs_robust_geometry" in
        *" $name "*) echo "SKIPPED $name: needs robust geometry (cells not star-shaped from their vertex mean)"; continue ;;
      esac
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
