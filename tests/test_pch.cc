// The source of rubberdyn_test_pch (see tests/CMakeLists.txt): the target
// only exists to build the precompiled header that every unit test reuses.
