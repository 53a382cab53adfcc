# Read by ctest after the discovered tests (CMakeLists.txt, TEST_INCLUDE_FILES):
# the long FE and study tests start first, so that with -j N they overlap
# the many short ones instead of running alone at the end. ctest learns the
# costs of a build folder after its first run; a fresh checkout (CI) has none.
# Seconds measured on a quiet core (docs/performance.md, "CI").
set(_rackopt_long_tests
  "RackOnSupportsFe.MeshPositionOnTheSupportsAtMidSpan" 100
  "FeCli.RealSolvesOnTheGantryDriveAtLevelZero" 90
  "FeShapeAndExtendedContact.ShapeOfTheLoadedMeshAndANeighbourInExtendedContact" 45
  "MeshPositionFe.SmallDriveInvariantsAndTheAnalyticModel" 44
  "MeshPositionFe.AMissedLoadIsCorrectedByASecondRun" 22
  "StudyAcceptance.RailwaySizingBeatsADenseGridAndRepeatsBitForBit" 17
  # Interrupted and resumed studies: about 30-60 s each under the sanitizers.
  "RunCli.KillNineThenResumeLosesNothingAndRepeatsNothing" 30
  "RunCli.ResumedRunReportsTheWarningsOfAnUninterruptedOne" 28
  "RunCli.CtrlCStopsCleanlyWritesResultsAndResumeFinishes" 16
  "OutputGuarantees.ProgressLineEndsDoneAndFitsTheTerminal" 9)
list(LENGTH _rackopt_long_tests _n)
math(EXPR _last "${_n} - 1")
foreach(_i RANGE 0 ${_last} 2)
  math(EXPR _j "${_i} + 1")
  list(GET _rackopt_long_tests ${_i} _name)
  list(GET _rackopt_long_tests ${_j} _cost)
  set_tests_properties("${_name}" PROPERTIES COST ${_cost})
endforeach()

# The CalculiX solves among them carry the label long_fe: `./dev.sh test` runs
# them after the rest, on their own (docs/fe.md, "Tests"). Their time limit is
# their idle cost times 15 (at least ctest's 600 s): on a 2-core machine busy
# with other builds they took 4-6 times their idle time, and a limit that does
# not grow with the solve fails the long ones only.
set(_rackopt_long_fe_tests
  "RackOnSupportsFe.MeshPositionOnTheSupportsAtMidSpan"
  "FeCli.RealSolvesOnTheGantryDriveAtLevelZero"
  "FeShapeAndExtendedContact.ShapeOfTheLoadedMeshAndANeighbourInExtendedContact"
  "MeshPositionFe.SmallDriveInvariantsAndTheAnalyticModel"
  "MeshPositionFe.AMissedLoadIsCorrectedByASecondRun")
foreach(_i RANGE 0 ${_last} 2)
  math(EXPR _j "${_i} + 1")
  list(GET _rackopt_long_tests ${_i} _name)
  list(GET _rackopt_long_tests ${_j} _cost)
  list(FIND _rackopt_long_fe_tests "${_name}" _fe)
  if(_fe GREATER -1)
    math(EXPR _limit "${_cost} * 15")
    if(_limit LESS 600)
      set(_limit 600)
    endif()
    set_tests_properties("${_name}" PROPERTIES LABELS long_fe TIMEOUT ${_limit})
  endif()
endforeach()
# A FIFO given as an input must be refused at once; should a change make
# rackopt wait on it again, these end at their limit instead of holding CI
# (each also kills a run still going after 20 s itself).
foreach(_t NonRegularInput.AFifoAsTheProblemFileIsRefusedByEveryCommand
           NonRegularInput.AFifoAsTheStudyFileIsRefusedAndNothingIsWritten
           NonRegularInput.AFifoAsTheProblemAStudyNamesIsRefused
           NonRegularInput.ACharacterDeviceIsRefusedNamingItsKind
           InputSize.FifoIsRefusedWithoutWaitingForAWriter)
  set_tests_properties("${_t}" PROPERTIES TIMEOUT 90)
endforeach()
