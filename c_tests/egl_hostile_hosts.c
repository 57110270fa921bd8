/*
 * egl_hostile_hosts.c: what a host process may do around the library, each case in a child
 * process whose stderr is captured (the library must print nothing) and whose exit status
 * says what it saw:
 *   - GL and EGL calls from an atexit handler, after the thread's locals are destroyed:
 *     GL calls are silent no-ops, eglMakeCurrent releasing succeeds, binding fails with
 *     EGL_BAD_ACCESS and eglGetError says so;
 *   - the same from a pthread-key destructor of an exiting thread;
 *   - render, fork(), render in the child: the child must not wait for its parent's worker
 *     threads (an alarm turns a hang into a failure);
 *   - native windows and pixmaps past the pbuffer limits: EGL_BAD_ALLOC, no abort.
 * ct:no-diff (EGLMemoryWindow / EGLMemoryPixmap are this implementation's native types)
 */
#define _POSIX_C_SOURCE 200809L
#include "common.h"

#include <pthread.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

static GLuint texture;

/* Exit status of a child whose checks failed (distinct from a crash or a signal). */
#define CHILD_FAILED 3

/* The checks made where the calling thread's locals are gone; a failure count. */
static int late_calls(void)
{
    int failed = 0;
    glDeleteTextures(1, &texture);
    failed += glGetError() != GL_NO_ERROR; /* no context: GL_NO_ERROR */
    glClear(GL_COLOR_BUFFER_BIT);
    failed += eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT) != EGL_TRUE;
    failed += eglGetError() != EGL_SUCCESS;
    failed += eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context) != EGL_FALSE;
    failed += eglGetError() != EGL_BAD_ACCESS;
    failed += eglGetCurrentContext() != EGL_NO_CONTEXT;
    return failed;
}

static void at_exit(void)
{
    if (late_calls() != 0)
        _exit(CHILD_FAILED);
}

static pthread_key_t key;

static void key_destructor(void *value)
{
    int *failed = (int *)value;
    *failed = late_calls();
}

static int key_failures = -1;

static void *thread_with_key(void *arg)
{
    (void)arg;
    pthread_setspecific(key, &key_failures);
    if (!eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context))
        return NULL;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glClear(GL_COLOR_BUFFER_BIT);
    return NULL; /* exits with the context current */
}

/* Many full-surface quads: enough band work for a flush on several threads. */
static void draw_quads(float r, float g, float b)
{
    static const GLfloat quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    int i;
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, quad);
    glColor4f(r, g, b, 1);
    for (i = 0; i < 16; ++i)
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glFinish();
}

/* Runs `body` in a child with stderr sent to a pipe; checks its exit status and that it
 * printed nothing. */
static void in_child(const char *what, int (*body)(void))
{
    int fds[2];
    pid_t pid;
    int status = 0;
    char buf[512];
    ssize_t n, total = 0;

    fflush(stdout);
    fflush(stderr);
    CHECK(pipe(fds) == 0);
    pid = fork();
    if (pid == 0) {
        close(fds[0]);
        dup2(fds[1], 2);
        alarm(60); /* a hang becomes SIGALRM */
        exit(body());
    }
    close(fds[1]);
    while ((n = read(fds[0], buf, sizeof buf - 1)) > 0) {
        buf[n] = 0;
        fprintf(stderr, "%s child stderr: %s", what, buf);
        total += n;
    }
    close(fds[0]);
    CHECK(waitpid(pid, &status, 0) == pid);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        fprintf(stderr, "%s child: status 0x%x\n", what, (unsigned)status);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    CHECK(total == 0);
}

static int atexit_case(void)
{
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    atexit(at_exit);
    return 0; /* exit() runs at_exit after the main thread's locals are destroyed */
}

static int key_destructor_case(void)
{
    pthread_t t;
    eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (pthread_key_create(&key, key_destructor) != 0)
        return CHILD_FAILED;
    if (pthread_create(&t, NULL, thread_with_key, NULL) != 0 || pthread_join(t, NULL) != 0)
        return CHILD_FAILED;
    /* The exited thread let the context go: this one can bind it. */
    if (key_failures != 0 || !eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context))
        return CHILD_FAILED;
    return 0;
}

static int fork_case(void)
{
    GLubyte p[4];
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    draw_quads(0, 0, 1);
    ct_read(3, 60, p);
    return p[0] == 0 && p[1] == 0 && p[2] == 255 ? 0 : CHILD_FAILED;
}

static int huge_native_surfaces(void)
{
    static const EGLint window_bits[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT | EGL_PIXMAP_BIT,
                                         EGL_RED_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_NONE};
    static unsigned char pixels[64];
    EGLMemoryWindow win = {100000, 100000, 400000, EGL_MEMORY_RGBA8888, NULL};
    EGLMemoryPixmap pm = {20000, 20000, 80000, EGL_MEMORY_RGBA8888, NULL};
    EGLMemoryWindow wide = {8193, 1, 8193 * 4, EGL_MEMORY_RGBA8888, NULL};
    EGLConfig cfg;
    EGLint n = 0;
    int failed = 0;

    win.pixels = pixels;
    pm.pixels = pixels;
    wide.pixels = pixels;
    if (!eglChooseConfig(ct.display, window_bits, &cfg, 1, &n) || n != 1)
        return CHILD_FAILED;
    failed += eglCreateWindowSurface(ct.display, cfg, &win, NULL) != EGL_NO_SURFACE;
    failed += eglGetError() != EGL_BAD_ALLOC;
    failed += eglCreatePixmapSurface(ct.display, cfg, &pm, NULL) != EGL_NO_SURFACE;
    failed += eglGetError() != EGL_BAD_ALLOC;
    failed += eglCreateWindowSurface(ct.display, cfg, &wide, NULL) != EGL_NO_SURFACE;
    failed += eglGetError() != EGL_BAD_ALLOC;
    return failed ? CHILD_FAILED : 0;
}

int main(void)
{
    /* Several workers, so the parent's flushes run on a pool the child does not have. */
    setenv("GLES_CM_THREADS", "4", 1);
    ct_init(64, 64);
    draw_quads(1, 0, 0);
    CHECK_PIXEL(3, 60, 255, 0, 0, 255, 0);

    in_child("atexit", atexit_case);
    in_child("key destructor", key_destructor_case);
    in_child("fork", fork_case);
    in_child("huge native surfaces", huge_native_surfaces);

    /* The parent renders on as before. */
    draw_quads(0, 1, 0);
    CHECK_PIXEL(3, 60, 0, 255, 0, 255, 0);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
