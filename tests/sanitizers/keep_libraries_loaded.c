/* keep_libraries_loaded: a dlclose() that unloads nothing, preloaded by scripts/sanitize.sh into every process of the
 * sanitizer test run. When the window closes (glfwTerminate closes the X display and the GL libraries), Mesa unloads
 * its driver (swrast_dri.so) and with it the globals that held the only pointers to two blocks it allocated; the
 * window's LeakSanitizer report at exit then lists them with a stack that ends in the unloaded library, which no
 * suppression can match. With libraries kept loaded the blocks stay reachable, and every leak of ours still shows.
 * Invariant: only for sanitizer runs; never linked into MeshEdit. */
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
