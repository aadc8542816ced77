#!/usr/bin/env bash
# Measures the practical limits of the vibrofric tool (tests/robustness/LIMITS.md): wall time and
# peak memory (/usr/bin/time -v, "Maximum resident set size") at large --digits, for large sample
# and Fourier files, and what happens just beyond each limit (message, exit status).
#   usage: tests/robustness/measure_limits.sh path/to/vibrofric [scratch-dir]
# Prints one markdown table row per measurement. VIBROFRIC_LIMIT_TIMEOUT (default 900) bounds each
# run; with 300 the whole script takes about 25 minutes on 2 cores.
set -uo pipefail
tool=${1:?usage: measure_limits.sh path/to/vibrofric [scratch-dir]}
scratch=${2:-$(mktemp -d)}
mkdir -p "$scratch"
limit=${VIBROFRIC_LIMIT_TIMEOUT:-900}
# VIBROFRIC_LIMIT_SECTIONS: any of digits, samples, fourier, waves, numbers (default: all).
sections=${VIBROFRIC_LIMIT_SECTIONS:-digits samples fourier waves numbers}
want() { case " $sections " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }

# run LABEL ARGS...: one table row: label | exit status | wall s | max RSS MiB | first 60 chars of
# stdout, or stderr when it failed.
run() {
  local label=$1
  shift
  local out=$scratch/out err=$scratch/err tv=$scratch/time
  timeout "$limit" /usr/bin/time -v -o "$tv" "$tool" "$@" >"$out" 2>"$err"
  local rc=$?
  local wall rss
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$tv" | awk -F: '{ if (NF == 3) print $1*3600 + $2*60 + $3; else print $1*60 + $2 }')
  rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$tv")
  local text
  if [ "$rc" -eq 0 ]; then text=$(head -c 60 "$out" | tr '\n' ' '); else text=$(head -c 160 "$err" | tr '\n' ' '); fi
  [ "$rc" -eq 124 ] && text="(killed after ${limit} s)"
  printf '| %s | %s | %s | %s | `%s` |\n' "$label" "$rc" "${wall:-?}" "$(awk -v k="${rss:-0}" 'BEGIN { printf "%.1f", k / 1024 }')" "$text"
}

echo "| case | exit | wall s | max RSS MiB | output (start) |"
echo "|---|---|---|---|---|"
if want digits; then
# Digits: the exact-area path (default), jumping (root finding for Eq. 8) and not.
for d in 50 1000 3000 10000; do
  run "mu sine beta=1 gamma=0.5 --digits $d" mu --wave sine --beta 1 --gamma 0.5 --digits "$d"
  run "mu sine beta=1 gamma=2 --digits $d" mu --wave sine --beta 1 --gamma 2 --digits "$d"
  run "mu power:2.5 beta=1 gamma=0.5 --digits $d" mu --wave power:2.5 --beta 1 --gamma 0.5 --digits "$d"
done
run "psi sine beta=1 --digits 10000" psi --wave sine --beta 1 --digits 10000
run "mu sine --digits 10001" mu --wave sine --beta 1 --gamma 0.5 --digits 10001
run "mu sine --digits 0" mu --wave sine --beta 1 --gamma 0.5 --digits 0
# The corner where the solver raises the working precision itself (beta -> 0).
run "mu sine beta=1e-30 gamma=-0.999 --digits 1000" mu --wave sine --beta 1e-30 --gamma=-0.999 --digits 1000
# The quadrature area path (tanh-sinh, 15 levels by default).
for d in 50 100 300 1000; do
  run "mu sine --area quadrature --digits $d" mu --wave sine --beta 1 --gamma 0.5 --area quadrature --digits "$d"
done
# Sweeps at 1000 digits (memory of a batch).
run "sweep sine 100 points --digits 1000" sweep --wave sine --beta 0.1:6:50 --gamma=-0.5,0.5 --digits 1000
run "sweep sine 10^5 points --type double" sweep --wave sine --beta 0.01:6:50000 --gamma=-0.5,0.5 --type double
fi

if want samples; then
# Sample files: a sampled sine with N samples, one per line.
for n in 100000 1000000 10000000; do
  f=$scratch/samples_$n.txt
  awk -v n="$n" 'BEGIN { for (j = 0; j < n; j++) printf "%.9f\n", sin(6.283185307179586 * j / n) }' >"$f"
  run "samples N=$n --type double" mu --wave "samples:$f" --beta 1 --gamma 0.5 --type double
  run "samples N=$n --digits 50" mu --wave "samples:$f" --beta 1 --gamma 0.5 --digits 50
done
run "samples N=10^6 --digits 1000" mu --wave "samples:$scratch/samples_1000000.txt" --beta 1 --gamma 0.5 --digits 1000
f=$scratch/samples_over.txt
awk 'BEGIN { for (j = 0; j <= 10000000; j++) print (j % 2) }' >"$f"
run "samples file of 10^7 + 1 lines" mu --wave "samples:$f" --beta 1 --gamma 0.5 --type double
# 10^7 samples on ONE line: the line limit does not apply.
f=$scratch/samples_one_line.txt
awk 'BEGIN { for (j = 0; j < 10000000; j++) printf "%d ", (j % 3); print "" }' >"$f"
run "samples 10^7 on one line --type double" mu --wave "samples:$f" --beta 1 --gamma 0.5 --type double
rm -f "$scratch"/samples_*.txt
fi

if want fourier; then

# Fourier files. Generic: harmonics 1..K with amplitude 1/k^2 and phase 1.3k (cost grows with K:
# the pieces come from a root search over 16K + 16 cells, each evaluation O(K)). Degenerate: the
# cosine series 1/k^2 with K = 4 has w' = w'' = w''' = 0 at phi = 1/2 (it hung the Lipschitz root
# search before 5ac3516).
for k in 10 30 100 300; do
  f=$scratch/fourier_$k.txt
  awk -v K="$k" 'BEGIN { for (j = 1; j <= K; j++) printf "%d %.6e %.6e\n", j, cos(1.3 * j) / (j * j), sin(1.3 * j) / (j * j) }' >"$f"
  run "fourier K=$k generic --type double" mu --wave "fourier:$f" --beta 1 --gamma 0.5 --type double
  run "fourier K=$k generic --digits 50" mu --wave "fourier:$f" --beta 1 --gamma 0.5 --digits 50
done
f=$scratch/fourier_degenerate.txt
printf '1 1 0\n2 0.25 0\n3 0.111111 0\n4 0.0625 0\n' >"$f"
run "fourier cosine 1/k^2 K=4 (w'=w''=0) --type double" mu --wave "fourier:$f" --beta 1 --gamma 0.5 --type double
run "fourier cosine 1/k^2 K=4 (w'=w''=0) --digits 50" mu --wave "fourier:$f" --beta 1 --gamma 0.5 --digits 50
f=$scratch/fourier_single_high.txt
echo "100000 0 1" >"$f"
run "fourier one harmonic k=100000 --type double" mu --wave "fourier:$f" --beta 1 --gamma 0.5 --type double
echo "100001 0 1" >"$f"
run "fourier k=100001" mu --wave "fourier:$f" --beta 1 --gamma 0.5 --type double
fi

if want waves; then
# power:P with flanks narrower than the working precision: escalated until resolved (PrecisionError
# without escalation); a sampled signal whose offset is 1e40 times its amplitude (normalised in
# mpfr with the cancelled digits; μ = 8/9).
run "power:1e30 beta=3 gamma=2 --type double" mu --wave power:1e30 --beta 3 --gamma 2 --type double
run "power:1e300 beta=3 gamma=2 --digits 50" mu --wave power:1e300 --beta 3 --gamma 2 --digits 50
run "power:1e300 beta=3 gamma=2 --type double --no-escalate=1" mu --wave power:1e300 --beta 3 --gamma 2 --type double --no-escalate=1
f=$scratch/samples_offset.txt
printf '1 1.0000000000000000000000000000000000000001 1\n' >"$f"
run "samples offset/amplitude 1e40 beta=3 gamma=2 --digits 50" mu --wave "samples:$f" --beta 3 --gamma 2 --digits 50
run "samples offset/amplitude 1e40 beta=3 gamma=2 --type double" mu --wave "samples:$f" --beta 3 --gamma 2 --type double
fi

if want numbers; then
# Long decimal strings (the number grammar was a std::regex until fa31caa).
for n in 1000 40000 100000; do
  run "--beta with $n digits" mu --wave sine --beta "0.$(head -c "$n" /dev/zero | tr '\0' 1)" --gamma 0.5 --digits 10
done
# Exponents: beyond double's range (an error), underflow (a value in mpfr), and 19 digits.
run "--beta 1e-400 --digits 20 (underflows double)" mu --wave sine --beta 1e-400 --gamma 0.5 --digits 20
run "--beta 1e-5000 --digits 20" mu --wave sine --beta 1e-5000 --gamma 0.5 --digits 20
run "--beta 1e400" mu --wave sine --beta 1e400 --gamma 0.5 --digits 20
run "--beta 1e-9223372036854775808 --type cpp_bin_float_50" mu --wave sine --beta 1e-9223372036854775808 --gamma 0.5 --type cpp_bin_float_50
run "--wave power:1e-5000" mu --wave power:1e-5000 --beta 1 --gamma 0.5
fi
