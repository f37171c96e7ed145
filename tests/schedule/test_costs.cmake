# The order `ctest -j` starts the long tests in. ctest starts tests in descending COST; without
# COST it learns each test's time from a previous run (Testing/Temporary/CTestCostData.txt), which
# a fresh clone (CI) does not have: there the declaration order held a 144-s test until late and
# left a core idle at the end while the RUN_SERIAL MPI tests waited for it. Seconds are the larger
# of the GCC Release and asan trees' recorded times on the 2-core machine, 2026-11-29; only their order
# matters. Applied by apply_costs.cmake; check_costs.cmake checks that every name is a test of the tree.
set(BB_TEST_COSTS
  SweepExtremes.AtSevenHarmonicsEverySweepReachesItsEndOrSaysWhere 144
  HbmSweepFold.ABridgeThatWandersAlongKinksIsNotTriedAgainFromTheSamePoint 75
  calibrate.verification.rig_modal_joint_identify 68
  inp.roundtrip.thesis.table06_glued_modal 50
  HbmCalibration.PeakDerivativesServeAsTheJacobian 62
  robust.table11_h13 59
  case.thesis.table11_periodic_100_60 39
  fidelity.sec342_slip_hysteresis_auto 34
  case.thesis.sec32_root_contact 34
  case.beyond.bladed_disk_vs_whole_forced_12 32
  case.verification.coulomb_oscillator_shooting_above 24
  case.thesis.table11_calibrate_contact_time 24
  calibrate.verification.rig_force_controlled_identify_uff 24
  calibrate.verification.rig_force_controlled_identify 24
  calibrate.verification.friction_oscillator_identify 20
  TimeContact.DamperHeldOnlyByFrictionMatchesHarmonicBalance 18
  TimeSolverFailure.AFirstHarmonicThatHoldsWithinTheEnvelopeToleranceGivesThePeak 18
  case.beyond.bladed_disk_vs_whole_forced 16
  HbmCalibration.ACrossCheckWithoutASolutionKeepsTheIdentification 14
  HbmPeakSensitivity.DamperPeaksMoveAsCentralDifferencesOfWholeRunsSay 14
  bad_input.mesh_exceeds_memory_hex20 13
  HbmSweepFold.AFoldTheBranchDoesNotComeBackFromIsBridgedOnceNotAtEveryFrequencyBeyondIt 13
  HbmFirstSolution.TableXIAt260NAndSevenHarmonicsClimbsFromFiveHarmonics 12
  HbmFrfSensitivity.DamperDlogColumnsAgreeWithCentralDifferencesOfWholeRuns 11
  FfrfRotatingModes.CampbellAtRestEqualsTheNonRotatingModalSolver 11
  install.examples 10
  case.thesis.table09_rom_vs_modal 10
  case.beyond.bladed_disk_cyclic_modal 10
  GeometricStiffness.ClampedColumnBucklesAtTheEulerLoad 10
  report.first_screen_in_browser 9
  case.thesis.sec32_root_contact_linear 9
  SweepExtremes.EverySweepReachesItsEndOrSaysWhereAndNoPeakSitsOnAFailure 9
  case.thesis.sec342_slip_hysteresis 8
  case.beyond.bladed_disk_dampers_whole 8
  calibrate.verification.friction_oscillator_identify_uff 8
  calibrate.verification.friction_oscillator_identify_frf 8
  HbmSteppedSineTest.RigJointComesBackFromCurvesWithDriftingForce 8)
