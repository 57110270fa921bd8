/*
 * child_hash.h: runs a scene in a child process whose library starts with a given
 * GLES_CM_THREADS (the library reads it once, when it loads), and returns the 64-bit hash
 * the child computed. For programs that compare images across thread counts; call it before
 * anything starts the library in the parent. Needs _POSIX_C_SOURCE 200809L before any
 * include.
 */
#ifndef CT_CHILD_HASH_H
#define CT_CHILD_HASH_H

#include <stdint.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

/* FNV-1a over `n` bytes, continuing from `h` (start with 1469598103934665603). */
static uint64_t ct_fnv1a(uint64_t h, const unsigned char *bytes, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i)
        h = (h ^ bytes[i]) * 1099511628211ull;
    return h;
}

/* `scene()` in a child with GLES_CM_THREADS = threads; its result, or 0 when the child could
 * not run or report. `scene` returns 0 for any failure of its own. */
static uint64_t ct_child_hash(const char *threads, uint64_t (*scene)(void))
{
    int fds[2];
    uint64_t hash = 0;
    pid_t pid;
    if (pipe(fds) != 0)
        return 0;
    pid = fork();
    if (pid == 0) {
        uint64_t h;
        setenv("GLES_CM_THREADS", threads, 1);
        h = scene();
        if (write(fds[1], &h, sizeof h) != (ssize_t)sizeof h)
            _exit(1);
        _exit(0);
    }
    close(fds[1]);
    if (pid > 0) {
        if (read(fds[0], &hash, sizeof hash) != (ssize_t)sizeof hash)
            hash = 0;
        waitpid(pid, NULL, 0);
    }
    close(fds[0]);
    return hash;
}

#endif /* CT_CHILD_HASH_H */
