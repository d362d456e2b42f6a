// The donor of the test suites' precompiled header (cmake/FilmDynPch.cmake): an executable built
// with the suites' own options, whose only job is to compile the header they all reuse.
int main() { return 0; }
