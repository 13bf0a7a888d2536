#!/usr/bin/env bash
# nibrig setup: installs the Debian packages the project needs (only when something is missing),
# builds, and runs one job:
#   ./setup.sh demo    build (Release) and run `nibrig demo` on the bundled default -> nibrig-demo/
#   ./setup.sh test    build the libraries' suites with ASan+UBSan and the faces' in Release, run every
#                      test suite, then fuzz the readers briefly
#   ./setup.sh bench   build (Release) and run the benchmarks with the scipy reference beside them
#   ./setup.sh panel   build (Release) and open nibrig-panel (extra arguments go to it)
#   ./setup.sh python  build the Python module and install it for this user (import nibrig)
#   ./setup.sh build   build (Release) only
#   ./setup.sh package build (Release) the command, the panel and the Python module, and pack them
#                      as Debian packages (CPack) -> build/release/packages/*.deb
#   ./setup.sh docs    build (Release) the command, the panel and the Python module, then the
#                      documentation site (ui/docs) -> build/docs/html
set -euo pipefail
cd "$(dirname "$0")"
root=$(pwd)
job=${1:-demo}
jobs=${NIBRIG_JOBS:-$(nproc)}

packages=(
  build-essential cmake pkg-config ninja-build ccache clang
  libeigen3-dev libspectra-dev liblbfgspp-dev libgmsh-dev libfftw3-dev libsndfile1-dev zlib1g-dev
  nlohmann-json3-dev libcli11-dev libspdlog-dev libboost-dev
  libplplot-dev plplot-driver-cairo
  librtaudio-dev libasound2-dev jackd2 libjack-jackd2-dev
  libusb-1.0-0-dev libumockdev-dev  # the rig's USB controller; its tests emulate the device with umockdev
  libinput-dev libudev-dev libwacom-dev  # pen tablets: read through libinput, named by libwacom
  lib3mf-dev libzip-dev  # a design's stylus exported as 3MF with lib3mf, whose pkg-config file links libzip
  avrdude  # `nibrig rig flash` writes the controller's firmware with it; its tests run it on a pty
  libstb-dev  # the report tests read their PNGs back with stb_image; the panel writes screenshots
  libimgui-dev libglfw3-dev  # the panel: ImGui 1.86 + GLFW + OpenGL 3
  pybind11-dev python3-dev python3-numpy  # the Python module in ui/python: numpy arrays in and out
  # A window without a screen or a GPU, for the panel, its tests and its benchmark: Xvfb, Mesa
  xvfb xauth libgl1-mesa-dri
  # The dependencies of the Debian packages, read from their binaries by dpkg-shlibdeps, which CPack
  # runs: it comes with build-essential, and is named here for what needs it
  dpkg-dev
  # Only the test job's: its suites, the emulated USB device, the sanitizers' runtime, fuzzers
  libgtest-dev libgmock-dev umockdev libclang-rt-14-dev python3-pytest
  groff-base desktop-file-utils  # the manual pages checked with groff, the desktop entry validated
  python3-nbclient python3-ipykernel python3-matplotlib  # the Python example notebook, executed by its test
  python3-sklearn  # SpaceEstimator's test runs scikit-learn's cross-validation on it
  python3-sphinx python3-myst-parser  # the documentation site in ui/docs: Sphinx, MyST for the Markdown; its tests build it
  mypy  # its stubtest checks the Python type hints against the compiled module
  # The exported styli's real consumers: PrusaSlicer slices the 3MF, admesh checks each STL, unzip
  # reads the 3MF's slicer settings as a reader that is not ours
  prusa-slicer admesh unzip
  # The test of the Debian packages: a fresh Debian 12 root to install them in, and lintian to check them
  mmdebstrap lintian
  # The rig controller's firmware in rig/firmware: Debian's AVR toolchain builds it, and simavr runs it
  # in the tests; libsimavr's pkg-config file needs libelf's
  gcc-avr binutils-avr avr-libc libsimavr-dev libelf-dev
  # Only the bench job's: Google Benchmark, the numpy and scipy references beside it
  libbenchmark-dev python3-scipy
)
# What each job does not need, left out of its install: the demo on a fresh machine is the first
# thing a new user waits for, and these bring in scipy, OpenBLAS, Mesa's drivers and an X server.
window=(xvfb xauth libgl1-mesa-dri)
test_only=(libgtest-dev libgmock-dev groff-base desktop-file-utils umockdev libclang-rt-14-dev python3-pytest python3-nbclient python3-ipykernel python3-matplotlib python3-sklearn mypy prusa-slicer admesh unzip gcc-avr binutils-avr avr-libc libsimavr-dev libelf-dev mmdebstrap lintian)
bench_only=(libbenchmark-dev python3-scipy)
# Only the test job's (its site tests) and the docs job's: Sphinx and MyST.
docs_only=(python3-sphinx python3-myst-parser)
# The demo builds the command alone (-DNIBRIG_BUILD_PANEL=OFF), plays nothing live, and runs no
# emulated USB device.
not_demo=(libimgui-dev libglfw3-dev libstb-dev libumockdev-dev jackd2 avrdude pybind11-dev python3-dev python3-numpy)

# ccache pays only from a warm cache: through a cold one a first build is slower, and CI and a new
# user always start cold. So it is used where its cache folder already exists:
# `mkdir -p ~/.cache/ccache` turns it on for rebuilds.
[ -d "${CCACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/ccache}" ] || export CCACHE_DISABLE=1

# Each stage's wall time on standard error, so that a CI log says where its minutes went.
stage_start=$(date +%s)
stage_done() {
  local now
  now=$(date +%s)
  echo "setup: $1 took $((now - stage_start)) s" >&2
  stage_start=$now
}

install_packages() {  # $@ = packages this job leaves out
  local missing=() skip=" $* "
  for p in "${packages[@]}"; do
    [[ $skip == *" $p "* ]] && continue
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "setup: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

configure_and_build() {  # $1 = build dir, rest = cmake options; $targets (if set) = what to build
  local dir=$1; shift
  cmake -S "$root" -B "$dir" -G Ninja "$@" >/dev/null
  stage_done "configuring $dir"
  cmake --build "$dir" -j "$jobs" ${targets:+--target $targets}
  stage_done "building $dir"
}

build_fuzzers() {  # libFuzzer needs clang; the readers are built again into each fuzz binary
  local out=$root/build/fuzz
  mkdir -p "$out"
  local pids=()
  for target in "$root"/tests/fuzz/fuzz_*.cpp; do
    local name
    name=$(basename "$target" .cpp)
    clang++ -std=c++20 -g -O1 -fsanitize=fuzzer,address,undefined -I"$root" -DNIBRIG_SOURCE_DIR="\"$root\"" \
      "$target" "$root"/model/io/*.cpp $(pkg-config --cflags --libs sndfile zlib lib3MF) -o "$out/$name" &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid"; done
}

run_fuzzer() {  # $1 = fuzz binary; its seeds are copied to a folder of its own, which it may add to
  local bin=$1 seconds=${NIBRIG_FUZZ_SECONDS:-20}
  local name corpus work
  name=$(basename "$bin")
  corpus=$root/tests/fuzz/corpus/${name#fuzz_}
  work=$(mktemp -d)
  [ -d "$corpus" ] || { echo "fuzz: $name has no seeds in $corpus"; return 1; }
  cp -r "$corpus"/. "$work"/
  # Every CSV seed also as a .gz twin, made here rather than committed: the readers take gzip
  # through zlib, so the compressed path is fuzzed from every format.
  for seed in "$work"/*.csv; do [ -f "$seed" ] && gzip -c "$seed" >"$seed.gz"; done
  echo "fuzz: $name for ${seconds} s"
  "$bin" -max_total_time="$seconds" -print_final_stats=1 "$work" 2>"$root/build/fuzz/$name.log" ||
    { tail -40 "$root/build/fuzz/$name.log"; echo "fuzz: $name found a crash"; return 1; }
  grep -E "stat::number_of_executed_units" "$root/build/fuzz/$name.log" || true
  rm -rf "$work"
}

run_fuzzers() {  # each fuzzer on a core of its own; fails when any found a crash
  local pids=() failed=0
  for bin in "$root"/build/fuzz/fuzz_*; do
    [ -x "$bin" ] && [ "${bin%.log}" = "$bin" ] || continue
    run_fuzzer "$bin" &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
  return $failed
}

case "$job" in
  test) install_packages "${bench_only[@]}" ;;
  bench) install_packages "${test_only[@]}" "${docs_only[@]}" ;;
  panel) install_packages "${test_only[@]}" "${bench_only[@]}" "${docs_only[@]}" ;;
  python) install_packages "${window[@]}" "${test_only[@]}" "${bench_only[@]}" "${docs_only[@]}" ;;
  demo) install_packages "${window[@]}" "${test_only[@]}" "${bench_only[@]}" "${not_demo[@]}" "${docs_only[@]}" ;;
  docs) install_packages "${window[@]}" "${test_only[@]}" "${bench_only[@]}" ;;
  *) install_packages "${window[@]}" "${test_only[@]}" "${bench_only[@]}" "${docs_only[@]}" ;;
esac
stage_done "installing packages"
# The tree a user runs (demo, panel, bench, build) and the test job's scenario tree are one: clang,
# Release. clang compiles this code faster than GCC 12, and the demo is the first wait.
release=(build/release -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release)
with_panel=-DNIBRIG_BUILD_PANEL=ON  # said each time: the demo's configuration of the tree leaves it OFF
case "$job" in
  demo)
    # The command alone: the panel is `./setup.sh panel`'s.
    targets=nibrig configure_and_build "${release[@]}" -DNIBRIG_BUILD_TESTS=OFF -DNIBRIG_BUILD_BENCH=OFF \
      -DNIBRIG_LEAK_CHECK=OFF -DNIBRIG_BUILD_PANEL=OFF
    # A nibrig-demo/ without the list of what a demo wrote there (an older nibrig's, or a folder of
    # one's own) cannot be replaced safely: it is kept under another name, and the demo writes anew.
    if [ -d nibrig-demo ] && [ ! -e nibrig-demo/.nibrig-files ] && [ -n "$(ls -A nibrig-demo)" ]; then
      kept="nibrig-demo.kept-$(date +%Y%m%d-%H%M%S)"
      mv nibrig-demo "$kept"
      echo "setup.sh: nibrig-demo/ holds no list of what a demo wrote there (an older nibrig's?): kept as $kept/"
    fi
    ./build/release/ui/nibrig demo -o nibrig-demo
    stage_done "running the demo"
    ;;
  test)
    # A test jackd that died with its process (a crashed test) keeps its slot in jack2's
    # machine-wide registry of 8 servers; with no jackd running, the registry can go.
    if ! pgrep -x jackd >/dev/null; then rm -f /dev/shm/jack-shm-registry /dev/shm/jack_sem.*nibrig-test-*; fi
    # Two trees, each test in one (the Tests page, ui/docs/development/tests.md). The libraries' own suites (label unit) under
    # ASan+UBSan, compiled by clang, which builds them with the sanitizers in well under GCC's
    # time. Line tables only (-g1): reports still name file and line.
    configure_and_build build/asan -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DNIBRIG_SANITIZE=ON -DNIBRIG_TESTS=unit -DNIBRIG_BUILD_BENCH=OFF -DNIBRIG_BUILD_FIRMWARE=ON \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
    # The faces end to end and the checks whose time is the feature (label scenario) in Release,
    # the build that plays, with LeakSanitizer linked in where the sanitizer build had it.
    configure_and_build "${release[@]}" -DNIBRIG_BUILD_TESTS=ON -DNIBRIG_TESTS=scenario \
      -DNIBRIG_BUILD_BENCH=OFF -DNIBRIG_LEAK_CHECK=ON "$with_panel" -DNIBRIG_BUILD_PYTHON=ON
    # One ctest over both trees, so that one scheduler fills the cores and the JACK tests of both
    # share one lock. One test more than cores: the JACK tests mostly wait on the audio clock.
    printf 'subdirs("asan" "release")\n' >build/CTestTestfile.cmake
    # What the tests keep in their user cache is solved again in each run, by the code under test.
    rm -rf build/asan/tests/scratch/user_cache build/release/tests/scratch/user_cache
    (cd build && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
       ctest --output-on-failure -j "$((jobs + 1))")
    stage_done "running the tests"
    build_fuzzers
    stage_done "building the fuzzers"
    run_fuzzers
    stage_done "fuzzing"
    ;;
  bench)
    configure_and_build "${release[@]}" -DNIBRIG_BUILD_TESTS=OFF -DNIBRIG_BUILD_BENCH=ON -DNIBRIG_LEAK_CHECK=OFF "$with_panel" \
      -DNIBRIG_BUILD_PYTHON=ON
    # The panel's frame benchmark needs a display: a private X server when there is none.
    display=()
    # -noreset: the benchmarks open one window after another, and a server that resets as its last
    # client leaves refused the next one ("Failed to open display").
    [ -z "${DISPLAY:-}" ] && display=(xvfb-run -a -s "-screen 0 1280x800x24 -noreset")
    "${display[@]}" ./build/release/tests/bench/nibrig_bench --benchmark_counters_tabular=true
    /usr/bin/python3 tests/bench/scipy_spectrogram.py
    /usr/bin/python3 tests/bench/numpy_space_fit.py
    PYTHONPATH=build/release/python /usr/bin/python3 tests/bench/python_space_fit.py
    ;;
  panel)
    configure_and_build "${release[@]}" -DNIBRIG_BUILD_TESTS=OFF -DNIBRIG_BUILD_BENCH=OFF -DNIBRIG_LEAK_CHECK=OFF "$with_panel"
    if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
      echo "setup: no display to open the panel on; on a machine without a screen, take a picture of a view:" >&2
      echo "  xvfb-run -a build/release/ui/panel/nibrig-panel --screenshot space.png --view space" >&2
      exit 1
    fi
    shift
    exec ./build/release/ui/panel/nibrig-panel "$@"
    ;;
  build)
    configure_and_build "${release[@]}" -DNIBRIG_BUILD_TESTS=OFF -DNIBRIG_BUILD_BENCH=OFF -DNIBRIG_LEAK_CHECK=OFF "$with_panel"
    ;;
  python)
    # The package folder the build assembled (ui/CMakeLists.txt) goes to the user's site-packages,
    # which Python searches without a package index, pip or a virtual environment.
    targets=nibrig_python_package configure_and_build "${release[@]}" -DNIBRIG_BUILD_TESTS=OFF -DNIBRIG_BUILD_BENCH=OFF \
      -DNIBRIG_LEAK_CHECK=OFF "$with_panel" -DNIBRIG_BUILD_PYTHON=ON
    site=$(/usr/bin/python3 -m site --user-site)
    mkdir -p "$site"
    rm -rf "$site/nibrig"
    cp -r build/release/python/nibrig "$site/nibrig"
    # Built for Debian's interpreter and its numpy: another python3 first on PATH (pyenv) may lack numpy.
    echo "setup: installed the Python module in $site/nibrig for /usr/bin/python3; try: /usr/bin/python3 -c 'import nibrig; print(nibrig.__all__)'"
    ;;
  package)
    # The tree every job shares, as `build` configures it, with the module: what the packages hold
    # (cmake/Package.cmake), installed under /usr.
    configure_and_build "${release[@]}" -DNIBRIG_BUILD_TESTS=OFF -DNIBRIG_BUILD_BENCH=OFF -DNIBRIG_LEAK_CHECK=OFF "$with_panel" \
      -DNIBRIG_BUILD_PYTHON=ON
    rm -f build/release/packages/*.deb
    (cd build/release && cpack)
    stage_done "packing"
    echo "setup: Debian packages in build/release/packages; install them with:"
    echo "  sudo apt install ./build/release/packages/*.deb"
    ;;
  docs)
    # The command pages come from the built command's --help and the Python reference from the
    # built module; warnings are errors, as in the tests.
    targets="nibrig nibrig-panel nibrig_python_package" configure_and_build "${release[@]}" -DNIBRIG_BUILD_TESTS=OFF \
      -DNIBRIG_BUILD_BENCH=OFF -DNIBRIG_LEAK_CHECK=OFF "$with_panel" -DNIBRIG_BUILD_PYTHON=ON
    NIBRIG_COMMAND=build/release/ui/nibrig NIBRIG_PANEL=build/release/ui/panel/nibrig-panel NIBRIG_PYTHON=build/release/python \
      /usr/bin/python3 -m sphinx -W --keep-going -b html ui/docs build/docs/html
    stage_done "building the site"
    echo "setup: the site is in build/docs/html/index.html"
    ;;
  *)
    echo "usage: ./setup.sh [demo|test|bench|panel|python|build|package|docs]" >&2
    exit 2
    ;;
esac
