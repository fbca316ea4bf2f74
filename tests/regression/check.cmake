# --check itself: a bound the run cannot meet makes it exit 3, naming the bound and the figure. (The node force
# balance and wall work it also asserts are tested against deliberate faults in tests/unit/test_node_balance.cpp.)
# 2D Sedov on 1k triangles has L1(density) 0.113 at first order on the scene's lattice (0.104 on gmsh's frontal mesh,
# 0.0824 there before the Dukowicz impedance, docs/cold-gas.md), so a bound of 0.01 cannot hold.
add_test(NAME check_fails_on_bound COMMAND bash ${SCRIPTS}/expect_check_failure.sh ${WORK}/check_fails
         "L1\\(density\\) error = 0\\.11[0-9]* exceeds 0\\.01" -- ${UNILAG} run ${SMALL_SEDOV} --check
         --set time.end=1 --set output.enabled=false --set exact.max_l1_density=0.01)
set_tests_properties(check_fails_on_bound PROPERTIES LABELS regression)
