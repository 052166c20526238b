// A deliberately bad test source for tests.no_fixed_paths_detects: the guard must report this line.
const char* kOutput = "/tmp/leftover/out.png";
