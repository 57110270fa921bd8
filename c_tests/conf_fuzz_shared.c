/*
 * conf_fuzz_shared: a seeded fuzzer of one share group used from several threads at once.
 * Each thread has its own context and pbuffer; all contexts share buffers, textures and
 * renderbuffers, whose names come from a small pool so that threads keep binding, updating,
 * mapping, drawing from and deleting the same objects under each other's feet.
 *
 * The program keeps to the application's side of the contract, and nothing more: a thread
 * writes through a mapped pointer only while the buffer is still bound and mapped in its own
 * context, and no thread respecifies (glBufferData) an object another thread has mapped.
 * Another thread may delete that object's name at any time: the mapping must stay valid,
 * which valgrind mode (GLES_CM_VALGRIND=1) checks byte by byte.
 *
 * After every GL call glGetError must return a defined code. CT_FUZZ_SEED (default 1) and
 * CT_FUZZ_CALLS (default 20000 per thread) change the run.
 * ct:no-diff (thread interleavings differ from run to run; there is no image to compare)
 */
#define _POSIX_C_SOURCE 200809L
#define GL_GLEXT_PROTOTYPES 1
#include "common.h"

#include <pthread.h>
#include <stdint.h>

#define THREADS 3
#define NAMES 8
#define STORE 1024

static const GLfloat quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
static GLubyte texels[16 * 16 * 4];

/* Guards the bookkeeping below, and the buffer calls that change what it records. */
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
/* Which buffer object each name reaches (numbered here; 0: none), and the last number. */
static int name_object[NAMES + 1];
static int objects;
/* The object each thread has mapped (0: none). */
static int mapped_object[THREADS];
static long bad_errors;
static long calls_per_thread = 20000;
static unsigned seed = 1;

struct worker {
    int index;
    uint64_t rng;
    EGLSurface surface;
    EGLContext context;
    GLuint array_buffer; /* the name bound to GL_ARRAY_BUFFER here (0: none) */
    int object;          /* the object bound there (it outlives a deleted name) */
    GLubyte *map;        /* this thread's mapping, or NULL */
};

static uint64_t rnd(struct worker *w)
{
    w->rng ^= w->rng >> 12;
    w->rng ^= w->rng << 25;
    w->rng ^= w->rng >> 27;
    return w->rng * 2685821657736338717ull;
}

static int rn(struct worker *w, int n) { return (int)(rnd(w) % (uint64_t)n); }

static void check(void)
{
    GLenum e = glGetError();
    if (e != GL_NO_ERROR && e != GL_INVALID_ENUM && e != GL_INVALID_VALUE &&
        e != GL_INVALID_OPERATION && e != GL_OUT_OF_MEMORY && e != 0x0506) {
        pthread_mutex_lock(&lock);
        ++bad_errors;
        pthread_mutex_unlock(&lock);
    }
}

/* Ends this thread's mapping (the buffer is still bound here, whatever others deleted). */
static void unmap(struct worker *w)
{
    if (!w->map)
        return;
    glUnmapBufferOES(GL_ARRAY_BUFFER);
    check();
    w->map = NULL;
    pthread_mutex_lock(&lock);
    mapped_object[w->index] = 0;
    pthread_mutex_unlock(&lock);
}

/* Whether another thread has object `o` mapped (call with the lock held). */
static int mapped_elsewhere(const struct worker *w, int o)
{
    int i;
    for (i = 0; i < THREADS; ++i)
        if (i != w->index && mapped_object[i] == o)
            return 1;
    return 0;
}

static void step(struct worker *w)
{
    GLuint name = 1 + (GLuint)rn(w, NAMES);
    GLint size = 0;
    switch (rn(w, 12)) {
    case 0: /* bind another array buffer (a mapping ends first: it needs its binding) */
        unmap(w);
        pthread_mutex_lock(&lock);
        w->array_buffer = rn(w, 4) ? name : 0;
        glBindBuffer(GL_ARRAY_BUFFER, w->array_buffer);
        if (w->array_buffer && name_object[name] == 0)
            name_object[name] = ++objects;
        w->object = w->array_buffer ? name_object[name] : 0;
        pthread_mutex_unlock(&lock);
        break;
    case 1: /* respecify, unless another thread has this object mapped */
        if (w->array_buffer == 0 || w->map)
            break;
        pthread_mutex_lock(&lock);
        if (!mapped_elsewhere(w, w->object))
            glBufferData(GL_ARRAY_BUFFER, STORE, NULL, GL_DYNAMIC_DRAW);
        pthread_mutex_unlock(&lock);
        break;
    case 2: /* map */
        if (w->array_buffer == 0 || w->map)
            break;
        pthread_mutex_lock(&lock);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
        if (!mapped_elsewhere(w, w->object) && size == STORE) {
            w->map = (GLubyte *)glMapBufferOES(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES);
            if (w->map)
                mapped_object[w->index] = w->object;
        }
        pthread_mutex_unlock(&lock);
        break;
    case 3: /* write the whole mapped store: positions of a quad, then filler */
        if (w->map) {
            memcpy(w->map, quad, sizeof quad);
            memset(w->map + sizeof quad, rn(w, 256), STORE - sizeof quad);
        }
        break;
    case 4:
        unmap(w);
        break;
    case 5: /* delete a name, whose object may be bound or mapped elsewhere */
        if (name == w->array_buffer)
            unmap(w); /* deleting unbinds it here, which may end the object's life */
        pthread_mutex_lock(&lock);
        glDeleteBuffers(1, &name);
        name_object[name] = 0;
        if (name == w->array_buffer) {
            w->array_buffer = 0;
            w->object = 0;
        }
        pthread_mutex_unlock(&lock);
        break;
    case 6: /* draw from the bound buffer, or from client memory */
        glEnableClientState(GL_VERTEX_ARRAY);
        if (w->array_buffer && !w->map)
            glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
        else
            glVertexPointer(2, GL_FLOAT, 0, quad);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glVertexPointer(2, GL_FLOAT, 0, quad); /* never leave a pointer into a buffer */
        break;
    case 7:
        glBindTexture(GL_TEXTURE_2D, rn(w, 4) ? name : 0);
        break;
    case 8:
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1 << rn(w, 5), 1 << rn(w, 5), 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, texels);
        break;
    case 9:
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        if (rn(w, 2))
            glEnable(GL_TEXTURE_2D);
        else
            glDisable(GL_TEXTURE_2D);
        break;
    case 10:
        glDeleteTextures(1, &name);
        break;
    default:
        switch (rn(w, 4)) {
        case 0:
            glBindRenderbufferOES(GL_RENDERBUFFER_OES, name);
            break;
        case 1:
            glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGB565_OES, 1 + rn(w, 16),
                                     1 + rn(w, 16));
            break;
        case 2:
            glDeleteRenderbuffersOES(1, &name);
            break;
        default:
            glFinish();
        }
    }
    check();
}

static void *run(void *arg)
{
    struct worker *w = (struct worker *)arg;
    long i;
    if (!eglMakeCurrent(ct.display, w->surface, w->surface, w->context)) {
        CHECK(!"eglMakeCurrent in a worker");
        return NULL;
    }
    for (i = 0; i < calls_per_thread; ++i)
        step(w);
    unmap(w);
    eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglReleaseThread();
    return NULL;
}

int main(void)
{
    static const EGLint size[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    struct worker workers[THREADS];
    pthread_t threads[THREADS];
    const char *v;
    int i;

    if ((v = getenv("CT_FUZZ_SEED")) != NULL)
        seed = (unsigned)strtoul(v, NULL, 10);
    if ((v = getenv("CT_FUZZ_CALLS")) != NULL)
        calls_per_thread = strtol(v, NULL, 10);
    for (i = 0; i < (int)sizeof texels; ++i)
        texels[i] = (GLubyte)(i * 7);
    ct_init(16, 16);
    eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    for (i = 0; i < THREADS; ++i) {
        workers[i].index = i;
        workers[i].rng = 0x9E3779B97F4A7C15ull * (uint64_t)(seed + 1) + (uint64_t)i;
        workers[i].surface = eglCreatePbufferSurface(ct.display, ct.config, size);
        workers[i].context = eglCreateContext(ct.display, ct.config, ct.context, NULL);
        workers[i].array_buffer = 0;
        workers[i].object = 0;
        workers[i].map = NULL;
        CHECK(workers[i].surface != EGL_NO_SURFACE && workers[i].context != EGL_NO_CONTEXT);
    }
    for (i = 0; i < THREADS; ++i)
        CHECK(pthread_create(&threads[i], NULL, run, &workers[i]) == 0);
    for (i = 0; i < THREADS; ++i)
        CHECK(pthread_join(threads[i], NULL) == 0);
    CHECK(bad_errors == 0);
    for (i = 0; i < THREADS; ++i) {
        CHECK(eglDestroySurface(ct.display, workers[i].surface));
        CHECK(eglDestroyContext(ct.display, workers[i].context));
    }
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    printf("%d threads x %ld calls, seed %u\n", THREADS, calls_per_thread, seed);
    return ct_done();
}
