# The 1D artery with the Pedley-Luo wall tension (docs/tube-artery.md 1.1, 2) through `unilag run` on
# inputs/artery_carotid_tension.yaml (the carotid with F_z = 1 N): it passes its own --check as shipped, the mean
# outlet pressure of a periodic RCR holds, summary.json states the tension, bad tension is refused. About 2 s.
set(CAROTID_TENSION_SCENE ${INPUTS}/artery_carotid_tension.yaml)

# --check: volume balance within 1e-10 (measured 8.3e-14) and periodic (1e-3) by the last of 8 cycles (after 5, as
# without tension); tube_modules: periodic within 6 cycles, mean outlet pressure mean(Q) (R1 + R2) = 12711 Pa within
# 1% (measured 12710.64); summary.json's T = F_z / (4 pi A0) = 3611.1 Pa.
add_test(NAME artery_tension_carotid_check COMMAND bash -c
         "rm -rf ${WORK}/artery_tension && ${UNILAG_TUBE_SH} ${CAROTID_TENSION_SCENE} --check \
          --output ${WORK}/artery_tension && ${PYTHON} ${SCRIPTS}/tube_modules.py artery ${WORK}/artery_tension \
          --cycles 6 && grep -Eq '\"tension_coefficient_Pa\": 3611\\.1' ${WORK}/artery_tension/summary.json \
          && echo artery_tension: PASS")
set_tests_properties(artery_tension_carotid_check PROPERTIES LABELS "tube;regression" PASS_REGULAR_EXPRESSION
                     "artery_tension: PASS" ENVIRONMENT "OMP_NUM_THREADS=1")

# Bad tension: exit 2, one message naming the file and key, nothing written.
add_test(NAME artery_error_negative_tension COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/artery_err_tension
         "artery_carotid_tension.yaml: key 'artery.tension': must be a non-negative number" -- ${UNILAG_TUBE}
         ${CAROTID_TENSION_SCENE} --set artery.tension=-1.0)
set_tests_properties(artery_error_negative_tension PROPERTIES LABELS "tube;regression")
# A wall as thick as the radius is outside the thin-wall law the tube's pressure comes from.
add_test(NAME artery_error_thick_wall COMMAND bash ${SCRIPTS}/expect_error.sh ${WORK}/artery_err_wall
         "artery_carotid_tension.yaml: key 'artery.wall_thickness': must be less than the radius" -- ${UNILAG_TUBE}
         ${CAROTID_TENSION_SCENE} --set artery.wall_thickness=0.01)
set_tests_properties(artery_error_thick_wall PROPERTIES LABELS "tube;regression")
