#!/usr/bin/env bash
# The GPU check of GRFLOW's KOKKOS styles, for loans of a GPU machine (one
# NVIDIA H100 or H200, CUDA 13, no internet, at most 10 minutes a command):
# build LAMMPS with GRFLOW and KOKKOS for CUDA from a carried tarball, run
# the KOKKOS tests on the GPU (against the plain styles on the host), time
# granular/grflow/kk against gran/hooke/history/kk on the jammed packing
# tiled to 8000, 64000 and 512000 spheres (the benchmark has no walls),
# and time the protocol deck itself: its shear stage with -sf kk against 2
# MPI ranks of the plain styles, sampled at the restart files of a carried
# run, and R concurrent runs on the one GPU (campaigns); the deck's
# preparation of a 64000-sphere sample on the GPU and its shear stage there
# and on 2 CPU cores.
#
#   scripts/gpu-check.sh pack KOKKOS [CARRY]      here, before the loan
#   scripts/gpu-check.sh build|test|bench|deck|campaign|big|all [CARRY]   on the GPU machine
#
# pack   makes CARRY (default build-gpu-carry/carry.tar.xz, git-ignored): the
#        LAMMPS 4Feb2025 source that the build needs (src/ and src/fmt/, the
#        packages GRANULAR and KOKKOS, cmake/; Debian's source package, fetched
#        by scripts/fetch-lammps-source.sh), the Kokkos source KOKKOS
#        (kokkos-4.5.01.tar.xz; kokkos/patches make it build with CUDA 13),
#        and the 8000-sphere packing of bench/in.prep_packing, made here
#        with an lmp given as LMP (default build-kokkos-openmp/lmp) unless
#        PACKING names one
# build  unpacks CARRY into build-gpu/, builds Kokkos (CUDA, the GPU's
#        architecture from nvidia-smi, else GRFLOW_KOKKOS_ARCH or HOPPER90)
#        and LAMMPS with the minimal set of LAMMPS KOKKOS styles
#        (scripts/setup-kokkos.sh cuda); a second call continues a build cut
#        short
# test   tests/python/test_kokkos.py on the GPU (pytest and numpy needed),
#        against the plain styles of the same lmp: granular/grflow/kk and
#        fix grflow/wall/kk (-sf kk chooses both)
# bench  bench/kokkos_bench.sh, TILES="1 2 4" (8000, 64000, 512000 spheres)
# deck   bench/sample_shear_speed.sh on the carried run (pack with RUN=DIR,
#        a run directory of the decks, e.g. the paper case's; EVERY=K
#        carries every K-th of its restart files): the shear stage's
#        steps/s at each restart file, "2 ranks" of the plain styles and
#        "gpu" (-sf kk), and the whole stage's time estimated from them;
#        DECK_NSTEPS steps per sample (default 20000), VARS the run's own
#        -var settings
# campaign  bench/kokkos_campaign.sh: R = RS (default "1 2 4 8") runs of
#        the carried run's shear stage at once on the GPU, CAMPAIGN_NSTEPS
#        steps each (default 20000), from its prep.restart (jammed) and from
#        its first restart file after initial liquefaction
# big    the decks at BIG_N spheres (default 64000; VARS as for deck): the
#        preparation (-var stage prep) with -sf kk on the GPU, timed, cut
#        at BIG_PREP_TIMEOUT seconds (default 420; then the log's last
#        rows say how far it came), and from its prep.restart (jammed)
#        the shear stage for BIG_NSTEPS steps (default 2000) with -sf kk
#        on the GPU and on 2 MPI ranks of the plain styles
#        (bench/shear_ab.sh): steps/s and the time breakdown of each.
#        Needs no carried run.  The liquefied rate at that size needs a
#        run into liquefaction (not made here).
# all    build, test, bench, deck and campaign (more than one loan: run
#        them one or two at a time)
#
# A loan of the GPU machine starts a bare machine (15 minutes of device
# time, at most 10 a command, the checkout only): build and measure in the
# same loan, one phase a command, in this order, from the repository root
# there, with build-gpu-carry carried:
#   scripts/gpu-check.sh build      (estimated 6-8 minutes on 16 cores; a
#                                    second call continues a build cut short)
#   TESTS='...' scripts/gpu-check.sh test    (TESTS: a pytest -k expression
#                                    to run part of the tests; default all)
#   scripts/gpu-check.sh bench
# and deck, campaign or big in a later loan.  None of this has run on a GPU
# yet, so these times are estimates; each phase writes its log into $OUT as
# it goes (the folder that comes back), so a phase cut short still says how
# far it came.
# Environment: GRFLOW_KOKKOS_ARCH (build), GRFLOW_KOKKOS_ARGS (test; default
# "-k on g 1 -sf kk -pk kokkos newton off neigh half gpu/aware off"), TESTS
# (test), KK, TILES, NSTEPS, NWARM, NSTEPS_<n>, BLOCKING (bench;
# bench/kokkos_bench.sh).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd -P)
phase=${1:?usage: gpu-check.sh pack KOKKOS [CARRY] | build|test|bench|deck|campaign|big|all [CARRY]}
shift
work=$top/build-gpu
lmp=$work/lammps-cuda/lmp
# the logs of every phase are written where they come back from the device
# machine as they grow ($OUT, so that a command cut at its time limit still
# returns what it did), else into build-gpu/logs
logs=${OUT:-$work/logs}
keep() {    # copy results to $OUT (the device machine's returned folder)
  [ -n "${OUT:-}" ] || return 0
  mkdir -p "$OUT"
  cp -r "$@" "$OUT/" 2> /dev/null || true
}
no_run="ERROR: no run in the carry: pack with RUN=DIR, a run directory of the decks (the paper \
case: bash bench/timed_case.sh run runs/case04 2 0,1, about 1.5 h on 2 cores; the quick preset: \
lmp -in inputs/cyclic_shear.lmp -var preset quick, about a minute)"
logged() {  # logged NAME CMD...: CMD's output on the screen and in $logs/NAME; CMD's status
  local name=$1
  shift
  mkdir -p "$logs"
  set +e
  "$@" 2>&1 | tee "$logs/$name"
  local rc=${PIPESTATUS[0]}
  set -e
  return "$rc"
}

case "$phase" in
pack)
  kokkos=${1:?usage: gpu-check.sh pack KOKKOS [CARRY]}
  carry=$(realpath -m "${2:-$top/build-gpu-carry/carry.tar.xz}")
  [ -f "$kokkos" ] || { echo "ERROR: no Kokkos tarball $kokkos" >&2; exit 1; }
  tree=$(bash "$top/scripts/fetch-lammps-source.sh" "${GRFLOW_CACHE_DIR:-$HOME/.cache/grflow}")
  stage=$(dirname "$carry")/pack
  rm -rf "$stage"
  mkdir -p "$stage/lammps-4Feb2025/src" "$stage/lammps-4Feb2025/doc"
  # src/: the top level with its fmt/ (the core) and the packages of the
  # KOKKOS build (GRANULAR, KOKKOS; OPENMP is staged empty but for GRFLOW's
  # files)
  find "$tree/src" -maxdepth 1 -type f -exec cp -p {} "$stage/lammps-4Feb2025/src/" \;
  cp -rp "$tree/src/fmt" "$tree/src/KOKKOS" "$tree/src/GRANULAR" "$stage/lammps-4Feb2025/src/"
  cp -rp "$tree/cmake" "$stage/lammps-4Feb2025/"
  cp -p "$tree/doc/lammps.1" "$stage/lammps-4Feb2025/doc/"
  cp -p "$kokkos" "$stage/kokkos.tar.${kokkos##*.tar.}"
  packing=${PACKING:-}
  if [ -z "$packing" ]; then
    plmp=${LMP:-$top/build-kokkos-openmp/lmp}
    [ -x "$plmp" ] || { echo "ERROR: no lmp $plmp to make the packing with (LMP=...)" >&2; exit 1; }
    mkdir -p "$stage/prep"
    echo "making the 8000-sphere packing with $plmp (bench/in.prep_packing; minutes)"
    (cd "$stage/prep" && "$plmp" -nocite -log log.prep -screen none \
       -in "$top/bench/in.prep_packing" -var outdir "$stage/prep") \
      || { tail -n 20 "$stage/prep/log.prep"; echo "ERROR: the packing failed" >&2; exit 1; }
    grep "^prepared packing" "$stage/prep/log.prep"
    packing=$stage/prep/packing.data
  fi
  cp -p "$packing" "$stage/packing.data"
  rm -rf "$stage/prep"
  # a run of the decks for the deck and campaign phases: its prepared
  # sample, every EVERY-th shear restart file (with checksum files), the
  # series, events and logs that the samplers read
  if [ -n "${RUN:-}" ]; then
    run=$(realpath "$RUN")
    [ -f "$run/prep.restart" ] || { echo "ERROR: RUN=$RUN has no prep.restart" >&2; exit 1; }
    mkdir -p "$stage/run"
    for f in prep.restart prep.restart.cksum prep.json series.txt events.txt log.shear.lammps; do
      [ -f "$run/$f" ] && cp -p "$run/$f" "$stage/run/"
    done
    i=0
    for k in $(ls "$run" | sed -n 's/^shear\.restart\.\([0-9]*\)$/\1/p' | sort -n); do
      if [ $((i % ${EVERY:-1})) -eq 0 ]; then
        cp -p "$run/shear.restart.$k" "$stage/run/"
        [ -f "$run/shear.restart.$k.cksum" ] && cp -p "$run/shear.restart.$k.cksum" "$stage/run/"
      fi
      i=$((i + 1))
    done
    echo "carried run $run: $(ls "$stage/run" | grep -c '^shear\.restart\.[0-9]*$') restart files"
  fi
  (cd "$stage" && find . -type f ! -name MANIFEST -print0 | LC_ALL=C sort -z | xargs -0 sha256sum > MANIFEST)
  tar -C "$stage" -cJf "$carry.tmp" .
  mv "$carry.tmp" "$carry"
  rm -rf "$stage"
  echo "carry: $carry ($(du -h "$carry" | cut -f1)); carry the folder $(realpath --relative-to="$top" "$(dirname "$carry")")"
  ;;

build)
  carry=$(realpath "${1:-$top/build-gpu-carry/carry.tar.xz}")
  start=$SECONDS
  mkdir -p "$work"
  if [ ! -f "$work/src/MANIFEST" ] || ! cmp -s "$carry" "$work/carry.tar"; then
    rm -rf "$work/src"
    mkdir -p "$work/src"
    tar -C "$work/src" -xf "$carry"
    (cd "$work/src" && sha256sum --quiet -c MANIFEST) || { echo "ERROR: $carry is damaged" >&2; exit 1; }
    cp "$carry" "$work/carry.tar"
    # another LAMMPS tree: staged afresh (the staging keys on its path only)
    rm -rf "$work/lammps-cuda/lammps-staged"
  fi
  arch=${GRFLOW_KOKKOS_ARCH:-}
  if [ -z "$arch" ]; then
    cap=$(nvidia-smi --query-gpu=compute_cap --format=csv,noheader 2> /dev/null | head -n 1 || true)
    case "$cap" in
      9.0) arch=HOPPER90 ;; 8.0) arch=AMPERE80 ;; 8.6) arch=AMPERE86 ;; 8.9) arch=ADA89 ;;
      7.5) arch=TURING75 ;; *) arch=HOPPER90 ;;
    esac
    echo "GPU compute capability ${cap:-unknown}: Kokkos architecture $arch"
  fi
  nvidia-smi -L || echo "(no nvidia-smi: building without a GPU here)"
  logged build.log env GRFLOW_KOKKOS_ARCH=$arch GRFLOW_KOKKOS_STYLES=${GRFLOW_KOKKOS_STYLES-minimal} \
    bash "$top/scripts/setup-kokkos.sh" cuda "$(ls "$work"/src/kokkos.tar.*)" "$work/lammps-cuda" \
      -- -D "LAMMPS_SOURCE_DIR=$work/src/lammps-4Feb2025" \
    || { echo "gpu-check build: FAILED after $(( SECONDS - start )) s" | tee -a "$logs/build.log"; exit 1; }
  echo "gpu-check build: $(( SECONDS - start )) s" | tee -a "$logs/build.log"
  ;;

test)
  [ -x "$lmp" ] || { echo "ERROR: no $lmp: run gpu-check.sh build first" >&2; exit 1; }
  py=
  # the build's venv first (it has the analysis' commands for the workflow
  # test), then any python3 with pytest and numpy
  for candidate in "$top/build/python/bin/python" python3 /usr/bin/python3; do
    if "$candidate" -c "import pytest, numpy" 2> /dev/null; then py=$candidate; break; fi
  done
  [ -n "$py" ] || { echo "ERROR: the tests need a python3 with pytest and numpy" >&2; exit 1; }
  mkdir -p "$work/tests" "$logs"
  start=$SECONDS
  select=()
  [ -n "${TESTS:-}" ] && select=(-k "$TESTS")
  rc=0
  logged pytest.log env -C "$work/tests" LMP_KOKKOS="$lmp" LMP="$lmp" OMP_NUM_THREADS=1 \
    GRFLOW_KOKKOS_THREADS="${GRFLOW_KOKKOS_THREADS:-0}" \
    GRFLOW_KOKKOS_ARGS="${GRFLOW_KOKKOS_ARGS:-"-k on g 1 -sf kk -pk kokkos newton off neigh half gpu/aware off"}" \
    GRFLOW_TEST_DECKS="$top/tests/decks" MPIEXEC="${MPIEXEC:-mpirun}" \
    PYTHONPATH="$top/analysis:$top/tests/python${PYTHONPATH:+:$PYTHONPATH}" \
    "$py" -m pytest -q -s -p no:cacheprovider --durations=15 --junitxml="$logs/junit.xml" \
      "${select[@]}" "$top/tests/python/test_kokkos.py" || rc=$?
  echo "gpu-check test: $(( SECONDS - start )) s, pytest status $rc" | tee -a "$logs/pytest.log"
  exit "$rc"
  ;;

bench)
  [ -x "$lmp" ] || { echo "ERROR: no $lmp: run gpu-check.sh build first" >&2; exit 1; }
  start=$SECONDS
  mkdir -p "$work/bench"
  rc=0
  logged bench.txt env TILES="${TILES:-1 2 4}" KK="${KK:--k on g 1 -sf kk -pk kokkos newton off neigh half}" \
    NSTEPS="${NSTEPS:-2000}" NWARM="${NWARM:-200}" NSTEPS_4="${NSTEPS_4:-500}" \
    bash "$top/bench/kokkos_bench.sh" "$lmp" "$work/src/packing.data" "$work/bench" || rc=$?
  echo "gpu-check bench: $(( SECONDS - start )) s, status $rc" | tee -a "$logs/bench.txt"
  nvidia-smi > "$logs/nvidia-smi.txt" 2>&1 || true
  keep "$work/bench"
  exit "$rc"
  ;;

deck)
  [ -x "$lmp" ] || { echo "ERROR: no $lmp: run gpu-check.sh build first" >&2; exit 1; }
  [ -d "$work/src/run" ] || { echo "$no_run" >&2; exit 1; }
  start=$SECONDS
  mkdir -p "$work/deck"
  kk=${KK_DECK:-"-k on g 1 -sf kk -pk kokkos newton off neigh half -var newton_pair off"}
  rc=0
  logged deck.txt env LMP="$lmp" OUT="$work/deck/sample" VARS="${VARS:-}" \
    bash "$top/bench/sample_shear_speed.sh" "$work/src/run" "${DECK_NSTEPS:-20000}" \
      "2 ranks|2|" "gpu|1||$kk" || rc=$?
  echo "gpu-check deck: $(( SECONDS - start )) s, status $rc" | tee -a "$logs/deck.txt"
  nvidia-smi > "$logs/nvidia-smi.txt" 2>&1 || true
  exit "$rc"
  ;;

campaign)
  [ -x "$lmp" ] || { echo "ERROR: no $lmp: run gpu-check.sh build first" >&2; exit 1; }
  run=$work/src/run
  [ -d "$run" ] || { echo "$no_run" >&2; exit 1; }
  start=$SECONDS
  # the first restart file after initial liquefaction (events.txt: step_IL)
  il=$(awk '!/^#/ && $7 >= 0 {print $7; exit}' "$run/events.txt" 2> /dev/null || true)
  files=(prep.restart)
  if [ -n "$il" ]; then
    k=$(ls "$run" | sed -n 's/^shear\.restart\.\([0-9]*\)$/\1/p' | sort -n | awk -v il="$il" '$1 > il {print; exit}')
    [ -n "$k" ] && files+=("shear.restart.$k")
  fi
  rc=0
  for f in "${files[@]}"; do
    logged "campaign.$f.txt" env RS="${RS:-1 2 4 8}" VARS="${VARS:-}" \
      KK="${KK_DECK:-"-k on g 1 -sf kk -pk kokkos newton off neigh half -var newton_pair off"}" \
      bash "$top/bench/kokkos_campaign.sh" "$lmp" "$run" "$f" "${CAMPAIGN_NSTEPS:-20000}" \
        "$work/campaign/$f" || rc=$?
    [ -f "$work/campaign/$f/results.txt" ] && cp "$work/campaign/$f/results.txt" "$logs/results.$f.txt"
  done
  echo "gpu-check campaign: $(( SECONDS - start )) s, status $rc" | tee -a "$logs/campaign.txt"
  exit "$rc"
  ;;

big)
  [ -x "$lmp" ] || { echo "ERROR: no $lmp: run gpu-check.sh build first" >&2; exit 1; }
  n=${BIG_N:-64000}
  nsteps=${BIG_NSTEPS:-2000}
  dir=$work/big/N$n
  rm -rf "$dir"
  mkdir -p "$dir/run"
  kk=${KK_DECK:-"-k on g 1 -sf kk -pk kokkos newton off neigh half -var newton_pair off"}
  extra=()
  read -r -a v <<< "${VARS:-}"
  for ((j = 0; j + 1 < ${#v[@]}; j += 2)); do extra+=(-var "${v[$j]}" "${v[$((j + 1))]}"); done
  # 1. the preparation on the GPU
  start=$SECONDS
  set +e
  # shellcheck disable=SC2086
  (cd "$dir" && OMP_NUM_THREADS=1 timeout "${BIG_PREP_TIMEOUT:-420}" "$lmp" $kk -nocite \
     -log none -screen none -in "$top/inputs/cyclic_shear.lmp" -var inputs "$top/inputs" \
     -var outdir "$dir/run" -var N "$n" -var stage prep "${extra[@]}")
  rc=$?
  set -e
  prep_s=$((SECONDS - start))
  loop=$(awk '/^Loop time/ {t += $4; s += $9} END {printf "%.0f s for %d steps", t, s}' \
    "$dir/run/log.prep.lammps" 2> /dev/null || true)
  {
    echo "# the decks at N = $n: preparation with -sf kk on the GPU"
    if [ -f "$dir/run/prep.restart" ]; then
      echo "preparation: $prep_s s wall (loop times: $loop), status $rc"
      grep "^GRFLOW prep: done" "$dir/run/log.prep.lammps" || true
    else
      echo "preparation NOT finished: status $rc after $prep_s s (loop times of the finished runs: ${loop:-none}); its last rows:"
      grep -E "^ +[0-9]+ +[0-9.e+-]+ " "$dir/run/log.prep.lammps" 2> /dev/null | tail -n 3 || true
    fi
  } | tee "$work/big/summary.N$n.txt"
  keep "$work/big/summary.N$n.txt" "$dir/run/log.prep.lammps"
  [ -f "$dir/run/prep.restart" ] || exit 1
  # 2. the shear stage from prep.restart: the GPU and 2 plain ranks, by
  # bench/shear_ab.sh (the script of the CPU side's record,
  # doc/studies/size-64000.md).  Its log summary runs on grflow-python;
  # without an installed one, the python3 here (it needs no package).
  py_build=${BUILD:-$top/build}
  if ! command -v grflow-python > /dev/null && [ ! -x "$py_build/python/bin/python" ]; then
    py_build=$work/python-shim
    mkdir -p "$py_build/python/bin"
    ln -sf "$(command -v python3)" "$py_build/python/bin/python"
  fi
  BUILD=$py_build LMP=$lmp OUT=$dir/ab VARS="${extra[*]}" \
    bash "$top/bench/shear_ab.sh" "$dir/run/prep.restart" "$nsteps" 1 "gpu|1|$kk" "ranks2|2|" \
    | tee -a "$work/big/summary.N$n.txt"
  echo "gpu-check big: $(( SECONDS - start )) s"
  nvidia-smi >> "$work/big/summary.N$n.txt" 2>&1 || true
  keep "$work/big/summary.N$n.txt"
  ;;

all)
  "$0" build "$@"
  "$0" test
  "$0" bench
  "$0" deck
  "$0" campaign
  ;;

*)
  echo "ERROR: unknown phase $phase: pack, build, test, bench, deck, campaign, big or all" >&2
  exit 1
  ;;
esac
