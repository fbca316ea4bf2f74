#!/usr/bin/env bash
# script_errors.sh PYTHON APPS_DIR: the study and plot scripts answer a bad argument (an unknown option, a folder
# without their input) with one error line and exit 2, never a Python traceback.
set -u
py=$1; apps=$2; fail=0
for s in ab_throughput plate_period rotation_study sedov_peak_study tube_artery_plot \
         tube_gas_rod_study_plot tube_helix_dispersion_plot tube_shock_study_plot tube_stability_plot \
         tube_wall_shock_study_plot; do
    for arg in --bogus /nonexistent_folder; do
        err=$("$py" "$apps/$s.py" "$arg" 2>&1 >/dev/null); rc=$?
        if [ "$rc" -ne 2 ] || echo "$err" | grep -q Traceback || ! echo "$err" | grep -q "^$s.py: error: "; then
            echo "FAIL: $s.py $arg: exit $rc: $err"; fail=1
        fi
    done
done
[ "$fail" -eq 0 ] && echo "script_errors: PASS"
