// Compiled into every program that links OPM (through the cutaway_opm target).
// Under the asan preset (CUTAWAY_SANITIZE): libopmcommon and the libpython it links allocate
// process-lifetime objects they never free. Those leaks are not ours; LeakSanitizer reads this hook.
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() { return "leak:libopmcommon.so\nleak:libpython3\n"; }
