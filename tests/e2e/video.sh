#!/usr/bin/env bash
# End-to-end: sequences moved out. --video writes MP4 (H.264) and WebM (VP9) with every frame at
# the size and rate asked (checked by video_probe, ffprobe's questions through the same FFmpeg
# libraries) and GIF; a frame of the MP4 stays close to the PNG it came from; --frame-range
# renders frames byte-identical to the same frames of the whole run (a turntable, an animated
# glTF with every state carried between frames: anchored pattern, line chains, strokes on a
# deforming mesh, ground, shadows, occlusion); the render-farm recipe (docs/render-farm.md) run
# with GNU parallel's local jobs; an interrupted run leaves no file; bad arguments exit 2 before
# anything renders.
set -u
viewer="$1"; probe="$2"; src="$3"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
expect() {  # expect STATUS DESCRIPTION -- command...
  local want="$1" what="$2"; shift 3
  "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" != "$want" ]; then echo "FAIL: $what: exit $got, expected $want"; tail -5 "$tmp/err"; fail=1; fi
}
bunny="$src/models/bunny.obj"; tube="$src/models/bending_tube.gltf"

# MP4: H.264 in 4:2:0, an odd size padded by a row and a column, every frame, 30 a second.
expect 0 "an MP4 turntable" -- "$viewer" --turntable 12 --size 65x49 --style crosshatch --video t.mp4 "$bunny"
got=$("$probe" t.mp4)
[ "$got" = "codec=h264 width=66 height=50 frames=12 pix_fmt=yuv420p fps=30/1" ] || { echo "FAIL: t.mp4: $got"; fail=1; }
[ -e turntable ] && { echo "FAIL: a turntable to --video also wrote a frames folder"; fail=1; }
grep -q "video written to t.mp4 (12 frames" "$tmp/err" || { echo "FAIL: the run does not say what it wrote: $(cat "$tmp/err")"; fail=1; }
# WebM: VP9, an animated scene's clock at --fps.
expect 0 "a WebM animation" -- "$viewer" --headless --frames 10 --fps 24 --size 64x48 --video a.webm "$tube"
got=$("$probe" a.webm)
[ "$got" = "codec=vp9 width=64 height=48 frames=10 pix_fmt=yuv420p fps=24/1" ] || { echo "FAIL: a.webm: $got"; fail=1; }
# GIF through --video.
expect 0 "a GIF through --video" -- "$viewer" --turntable 6 --size 40x30 --video t.gif "$bunny"
oiiotool --info t.gif | grep -q "6 subimages" || { echo "FAIL: t.gif: $(oiiotool --info t.gif)"; fail=1; }
ls -a | grep -q partial && { echo "FAIL: partial files left: $(ls -a)"; fail=1; }

# What the codec does to hatching: frame 3 of the MP4 against the PNG it was made from.
expect 0 "an MP4 beside its frames" -- "$viewer" --turntable 8 --size 320x240 --style crosshatch --video q.mp4 --save-frames q "$bunny"
"$probe" q.mp4 3 q3.ppm >/dev/null || { echo "FAIL: frame 3 of q.mp4 not decoded"; fail=1; }
psnr=$(oiiotool q/frame-0003.png --ch R,G,B q3.ppm --diff 2>&1 | sed -n 's/.*Peak SNR = \([0-9.]*\).*/\1/p' | head -1)
awk -v p="${psnr:-0}" 'BEGIN { exit !(p >= 35) }' || { echo "FAIL: frame 3 of the MP4 is far from its PNG: PSNR ${psnr:-none} dB (at least 35)"; fail=1; }

# --frame-range: frames 3 to 5 alone equal frames 3 to 5 of the whole run.
same_range() {  # same_range NAME ARGS... (a sequence of 8 frames)
  local name="$1"; shift
  "$viewer" --headless --size 96x72 --save-frames "$name-whole" "$@" 2>"$tmp/err" || { echo "FAIL: $name: the whole run failed"; cat "$tmp/err"; fail=1; return; }
  "$viewer" --headless --size 96x72 --save-frames "$name-part" --frame-range 3-5 "$@" 2>"$tmp/err" || { echo "FAIL: $name: the range failed"; cat "$tmp/err"; fail=1; return; }
  [ "$(ls "$name-part" | tr '\n' ' ')" = "frame-0003.png frame-0004.png frame-0005.png " ] || { echo "FAIL: $name: the range wrote $(ls "$name-part")"; fail=1; }
  for f in 3 4 5; do
    cmp -s "$name-whole/frame-000$f.png" "$name-part/frame-000$f.png" || { echo "FAIL: $name: frame $f rendered alone differs from the whole run's"; fail=1; }
  done
  cmp -s "$name-whole/frame-0003.png" "$name-whole/frame-0004.png" && { echo "FAIL: $name: the sequence does not move"; fail=1; }
}
same_range turntable-anchored --turntable 8 --style crosshatch --pattern anchored "$bunny"
same_range turntable-dashed --turntable 8 --style technical "$bunny"
same_range tube-painterly --frames 8 --fps 7 --style painterly --pattern anchored "$tube"
same_range tube-illustrated --frames 8 --fps 7 --style illustrated --animate orbit:5,zoom:1.02 "$tube"

# The farm recipe with parallel's local jobs: three shares of a 12-frame turntable, then the
# frames together equal the single run's.
"$viewer" --turntable 12 --size 96x72 --pattern anchored --save-frames single "$bunny" 2>/dev/null
printf '0 3\n4 7\n8 11\n' > shares.txt
parallel -j2 --colsep ' ' "$viewer" --turntable 12 --size 96x72 --pattern anchored --save-frames farm --frame-range {1}-{2} "$bunny" :::: shares.txt 2>/dev/null ||
  { echo "FAIL: parallel's jobs failed"; fail=1; }
[ "$(ls farm | wc -l)" = 12 ] || { echo "FAIL: the farm wrote $(ls farm | wc -l) frames"; fail=1; }
for f in single/frame-*.png; do cmp -s "$f" "farm/$(basename "$f")" || { echo "FAIL: farm frame $(basename "$f") differs from the single run's"; fail=1; }; done

# Interrupted: nothing under the video's name, no partial file left.
"$viewer" --turntable 3600 --size 320x240 --video stopped.mp4 "$bunny" 2>"$tmp/stopped.err" &
pid=$!
for _ in $(seq 100); do [ -e .stopped.partial.mp4 ] && break; sleep 0.1; done
sleep 0.3; kill -INT "$pid"; wait "$pid"; rc=$?
[ "$rc" = 130 ] || { echo "FAIL: an interrupted run exits $rc, expected 130"; cat "$tmp/stopped.err"; fail=1; }
[ -e stopped.mp4 ] || [ -e .stopped.partial.mp4 ] && { echo "FAIL: an interrupted run left $(ls -a | grep stopped)"; fail=1; }
grep -q "interrupted at frame" "$tmp/stopped.err" || { echo "FAIL: the interruption is not said: $(tail -2 "$tmp/stopped.err")"; fail=1; }

# Bad arguments: exit 2, said before anything renders.
expect 2 "--video .avi" -- "$viewer" --turntable 4 --video t.avi "$bunny"
grep -q ".mp4 (H.264), .webm (VP9) or .gif" "$tmp/err" || { echo "FAIL: an unknown extension does not list the formats: $(cat "$tmp/err")"; fail=1; }
expect 2 "--video into a missing folder" -- "$viewer" --turntable 4 --video none/t.mp4 "$bunny"
expect 2 "--video without a sequence" -- "$viewer" --headless --video t2.mp4 "$bunny"
expect 2 "--video-quality 60" -- "$viewer" --turntable 4 --video t2.mp4 --video-quality 60 "$bunny"
expect 2 "--video-quality without --video" -- "$viewer" --turntable 4 --video-quality 20 "$bunny"
expect 2 "--frame-range backwards" -- "$viewer" --turntable 12 --frame-range 5-3 "$bunny"
expect 2 "--frame-range past the end" -- "$viewer" --turntable 12 --frame-range 0-12 "$bunny"
grep -q "frames 0..11" "$tmp/err" || { echo "FAIL: --frame-range past the end does not name the frames: $(cat "$tmp/err")"; fail=1; }
expect 2 "--frame-range x" -- "$viewer" --turntable 12 --frame-range x "$bunny"
expect 2 "--frame-range without a sequence" -- "$viewer" --headless --frame-range 0-3 "$bunny"
[ -e t2.mp4 ] && { echo "FAIL: a refused run wrote t2.mp4"; fail=1; }
exit $fail
