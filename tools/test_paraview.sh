#!/usr/bin/env bash
# The real-client test (`make test-paraview`): short WCSPH, MPS, MPH-I, 3D, shallow-water and heat runs opened in ParaView's
# own readers (XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT and OpenDataFile's choice) under a virtual
# display. tools/paraview_check.py asserts point and cell counts, array names and components,
# the frame times and a non-empty picture per reader; then `ryushi render` (PNGs, MP4, a 3D
# slice, a refusal). Usage: tools/test_paraview.sh BUILD_DIR
# [IMAGE_DIR] (the screenshots go to IMAGE_DIR, default BUILD_DIR/paraview).
set -euo pipefail
build=${1:-build}
images=${2:-$build/paraview}
work=$build/paraview_runs
rm -rf "$work"
mkdir -p "$work" "$images"
ryushi=$build/ryushi

points() { sed -n 's/^  "particles": \([0-9]*\),$/\1/p' "$1/summary.json"; }

check() {  # label out times [extra options]
  local label=$1 out=$2 times=$3
  shift 3
  xvfb-run -a -s "-screen 0 1024x768x24" pvpython tools/paraview_check.py "$out" \
    --expect-points "$(points "$out")" --expect-times "$times" --image-dir "$images" --label "$label" "$@" \
    2> >(grep -v -e '^$' -e 'vtkXOpenGLRenderWindow' -e 'GLX' >&2)
}

# WCSPH 2D with a tensor field (the moment matrix M_i of the free-surface system, 3 x 3 in 2D).
scene=$work/dam_break_2d_tensor.toml
cp scenes/dam_break_2d.toml "$scene"
printf '\n[[systems]]\nname = "free_surface_detection"\nmoment_matrix = true\n' >>"$scene"
"$ryushi" run "$scene" --out "$work/wcsph" --quiet --end-time 0.04 --set particles.spacing=0.0125 \
  --set output.interval=0.02 --set 'output.fields=["moment_matrix", "surface_normal", "free_surface"]'
check wcsph "$work/wcsph" 0,0.02,0.04 --tensors moment_matrix --arrays velocity,pressure,density,kind,id,surface_normal

"$ryushi" run scenes/dam_break_mps_2d.toml --out "$work/mps" --quiet --end-time 0.04 \
  --set particles.spacing=0.0125 --set output.interval=0.02
check mps "$work/mps" 0,0.02,0.04

"$ryushi" run scenes/dam_break_3d.toml --out "$work/wcsph_3d" --quiet --end-time 0.02 \
  --set output.interval=0.01
check wcsph_3d "$work/wcsph_3d" 0,0.01,0.02
# Shallow water: the particles drawn on the water surface (z = surface_elevation), coloured by depth.
"$ryushi" run scenes/dam_break_ritter_swe.toml --out "$work/swe" --quiet --end-time 0.1 --set output.interval=0.05
check swe "$work/swe" 0,0.05,0.1 --arrays velocity,pressure,kind,id,depth,area,volume,surface_elevation \
  --color depth --z-equals surface_elevation
# The particles a scene makes before it runs (`check --write-initial`): an STL sphere in a tank.
made=$("$ryushi" check scenes/dam_break_sphere_3d.toml --write-initial "$work/stl_initial" | sed -n 's/.*, \([0-9]*\) particles,.*/\1/p')
xvfb-run -a -s "-screen 0 1024x768x24" pvpython tools/paraview_check.py "$work/stl_initial" \
  --expect-points "$made" --expect-times 0 --image-dir "$images" --label stl_initial --arrays kind,body \
  2> >(grep -v -e '^$' -e 'vtkXOpenGLRenderWindow' -e 'GLX' >&2)
# A round container (its walls on the fluid's lattice outside the circle) with the force on it.
"$ryushi" run scenes/round_tank_2d.toml --out "$work/round_tank" --quiet --end-time 0.1 --set output.interval=0.05
check round_tank "$work/round_tank" 0,0.05,0.1
# Heat and a temperature-dependent viscosity (docs/multiphysics.md): coloured by temperature.
"$ryushi" run scenes/cooling_slump_2d.toml --out "$work/cooling" --quiet --end-time 0.1 --set output.interval=0.05
check cooling "$work/cooling" 0,0.05,0.1 --arrays velocity,pressure,kind,id,temperature,viscosity,shear_rate \
  --color temperature
# An elastic plate (docs/multiphysics.md): its Cauchy stress as a 3 x 3 tensor, coloured by displacement.
"$ryushi" run scenes/elastic_plate_2d.toml --out "$work/elastic" --quiet --end-time 0.04 --set particles.spacing=0.004 \
  --set output.interval=0.02
check elastic "$work/elastic" 0,0.02,0.04 --tensors stress --arrays velocity,kind,id,displacement,solid_pressure \
  --color displacement
# Surface tension (docs/surface_tension.md): curvature, the Laplace pressure, the normal (a vector).
"$ryushi" run scenes/square_drop_2d.toml --out "$work/square_drop" --quiet --end-time 0.008
check square_drop "$work/square_drop" 0,0.004,0.008 --arrays velocity,pressure,curvature,surface_pressure,tension_normal \
  --color surface_pressure
# MPH-I (docs/mph.md): the viscous dam break, coloured by pressure, with its number density.
"$ryushi" run scenes/dam_break_viscous_mph_2d.toml --out "$work/mph" --quiet --end-time 0.02 --set output.interval=0.01
check mph "$work/mph" 0,0.01,0.02 --arrays velocity,pressure,density,kind,id,number_density
echo "test-paraview: 10 particle sets x 4 readers passed; screenshots in $images"

# Pictures without ParaView: every frame and a movie, a 3D slice, and a clean refusal.
"$ryushi" render "$work/wcsph" --movie >/dev/null
frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 \
  "$work/wcsph/render/pressure.mp4")
[ "$frames" = 3 ] || { echo "test-paraview: pressure.mp4 has $frames frames, expected 3" >&2; exit 1; }
[ "$(ls "$work/wcsph/render"/pressure_*.png | wc -l)" = 3 ] || { echo "test-paraview: expected 3 PNGs" >&2; exit 1; }
"$ryushi" render "$work/wcsph_3d" --frames last --field velocity --slice y=0.1 >/dev/null
[ -s "$work/wcsph_3d/render/velocity_00002.png" ] || { echo "test-paraview: no 3D slice picture" >&2; exit 1; }
mkdir -p "$work/empty"
if "$ryushi" render "$work/empty" 2>"$work/empty.err"; then echo "test-paraview: render of no frames succeeded" >&2; exit 1; fi
grep -q "no frames" "$work/empty.err" || { echo "test-paraview: unexpected message: $(cat "$work/empty.err")" >&2; exit 1; }
# --movie without ffmpeg (none on PATH): exit 2 before any picture (it rendered every PNG first).
status=0; PATH=/nonexistent "$ryushi" render "$work/wcsph" --movie --dest "$work/no_ffmpeg" 2>"$work/movie.err" || status=$?
[ "$status" = 2 ] && grep -q "needs ffmpeg, which is not installed" "$work/movie.err" && [ ! -e "$work/no_ffmpeg" ] ||
  { echo "test-paraview: --movie without ffmpeg: exit $status, $(cat "$work/movie.err")" >&2; exit 1; }
# A folder that cannot be written (below a file: root writes read-only ones): exit 4 and one
# line (it was a Python traceback).
touch "$work/a_file"
status=0; "$ryushi" render "$work/wcsph" --dest "$work/a_file/render" 2>"$work/dest.err" || status=$?
[ "$status" = 4 ] && grep -q "^ryushi render: could not write $work/a_file/render: " "$work/dest.err" &&
  [ "$(wc -l <"$work/dest.err")" = 1 ] ||
  { echo "test-paraview: render into an unwritable folder: exit $status, $(cat "$work/dest.err")" >&2; exit 1; }
# sweep.png's labels say which axis is logarithmic (a decade or more) and which is not (it once
# said "log axes" on linear ones).
printf 'run,status,wall_time_s,x_error\na,completed,1.0,0.5\nb,completed,1.5,0.004\n' >"$work/sweep.csv"
labels=$(/usr/bin/python3 tools/plot_sweep.py "$work/sweep.csv" "$work/sweep.png")
[ "$labels" = "$work/sweep.png: x wall time (s), y x_error (log scale)" ] ||
  { echo "test-paraview: sweep.png labels: $labels" >&2; exit 1; }
echo "test-paraview: ryushi render wrote PNGs, a 3-frame MP4 and a 3D slice; refused an empty run, a movie" \
  "without ffmpeg and an unwritable folder"
