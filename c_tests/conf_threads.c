/*
 * conf_threads: many contexts on many threads rendering at once. THREADS threads each make
 * their own context current on their own pbuffer and draw the same scene (lit, textured,
 * fogged, blended, depth- and stencil-tested, from client arrays and buffer objects) for
 * FRAMES frames, flushing as they go. Half of the contexts share one group of objects (a
 * texture and a vertex buffer the main thread made, only read by the threads); the others
 * make their own. Every frame of every thread must equal, byte for byte, the same frame
 * rendered on the main thread alone beforehand.
 */
#define _POSIX_C_SOURCE 200809L
#include "common.h"

#include <pthread.h>

#define THREADS 8
#define FRAMES 6
#define W 64
#define H 48

static EGLDisplay dpy;
static EGLConfig cfg;

/* Objects of the shared group, made by the main thread in `share_root`. */
static EGLContext share_root;
static GLuint shared_tex, shared_vbo;

static const GLfloat strip[] = {
    /* x, y, z, nx, ny, nz, s, t */
    -1.0f, -1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f,
    1.0f,  -1.0f, 0.2f, 0.3f, 0.0f, 1.0f, 2.0f, 0.0f,
    -1.0f, 1.0f,  -0.2f, 0.0f, 0.3f, 1.0f, 0.0f, 2.0f,
    1.0f,  1.0f,  0.0f, 0.3f, 0.3f, 1.0f, 2.0f, 2.0f,
};
static const GLubyte colors[] = {255, 0, 0, 128, 0, 255, 0, 200, 0, 0, 255, 255, 255, 255, 0, 64};
static const GLshort fan[] = {0, 0, 30, 0, 20, 25, -5, 35, -25, 20, -30, -5};

static GLuint make_texture(void)
{
    GLubyte texels[16 * 16 * 4];
    GLuint t = 0;
    int x, y;
    for (y = 0; y < 16; ++y)
        for (x = 0; x < 16; ++x) {
            GLubyte *p = texels + 4 * (y * 16 + x);
            int on = ((x >> 2) ^ (y >> 2)) & 1;
            p[0] = (GLubyte)(on ? 240 : 30);
            p[1] = (GLubyte)(x * 16);
            p[2] = (GLubyte)(y * 16);
            p[3] = (GLubyte)(on ? 255 : 160);
        }
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

static GLuint make_vbo(void)
{
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, sizeof strip, strip, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return b;
}

/* Frame `f` of the scene, into the current surface; returns its pixels in `out`. */
static void render(int f, GLuint tex, GLuint vbo, GLubyte *out)
{
    static const GLfloat light_pos[] = {0.5f, 1.0f, 2.0f, 0.0f};
    static const GLfloat fog_color[] = {0.2f, 0.2f, 0.3f, 1.0f};
    glViewport(0, 0, W, H);
    glClearColor(0.1f, 0.1f * (GLfloat)f, 0.2f, 1);
    glClearDepthf(1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustumf(-0.6f, 0.6f, -0.45f, 0.45f, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -3.2f);
    glRotatef(15.0f * (GLfloat)f, 0.3f, 1, 0.1f);

    /* A lit, textured, fogged strip from the vertex buffer, stencil marking it. */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_FOG);
    glFogf(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2.5f);
    glFogf(GL_FOG_END, 5.0f);
    glFogfv(GL_FOG_COLOR, fog_color);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 8 * sizeof(GLfloat), (const void *)0);
    glNormalPointer(GL_FLOAT, 8 * sizeof(GLfloat), (const void *)(3 * sizeof(GLfloat)));
    glTexCoordPointer(2, GL_FLOAT, 8 * sizeof(GLfloat), (const void *)(6 * sizeof(GLfloat)));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glFlush();
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_FOG);
    glDisable(GL_LIGHTING);

    /* A blended fan in window-ish coordinates, only where the strip is not. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(-40, 40, -30, 30, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(-20.0f * (GLfloat)f, 0, 0, 1);
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(1, 0.8f, 0.1f, 0.6f);
    glVertexPointer(2, GL_SHORT, 0, fan);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 6);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);

    /* Smooth lines and big points on top. */
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glLineWidth(2.5f);
    glColor4f(0.2f, 1, 1, 1);
    glDrawArrays(GL_LINE_LOOP, 0, 6);
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_BLEND);
    glPointSize(4);
    glColor4f(1, 1, 1, 1);
    glDrawArrays(GL_POINTS, 0, 6);
    glDisableClientState(GL_VERTEX_ARRAY);
    glColor4f(1, 1, 1, 1);

    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, out);
}

static GLubyte reference[FRAMES][W * H * 4];

struct job {
    int index;
    int shared;
    int mismatched_frames;
    int first_bad_frame;
    GLenum error;
    int ok;
    pthread_t thread;
};

static pthread_barrier_t start;

static void *worker(void *arg)
{
    struct job *j = (struct job *)arg;
    static const EGLint pb[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
    EGLSurface s = eglCreatePbufferSurface(dpy, cfg, pb);
    EGLContext c = eglCreateContext(dpy, cfg, j->shared ? share_root : EGL_NO_CONTEXT, NULL);
    GLubyte *pixels = (GLubyte *)malloc(W * H * 4);
    GLuint tex, vbo;
    int f;

    j->first_bad_frame = -1;
    j->ok = s != EGL_NO_SURFACE && c != EGL_NO_CONTEXT && pixels != NULL &&
            eglMakeCurrent(dpy, s, s, c);
    if (j->ok && j->shared) {
        tex = shared_tex;
        vbo = shared_vbo;
    } else if (j->ok) {
        tex = make_texture();
        vbo = make_vbo();
    } else {
        tex = vbo = 0;
    }
    pthread_barrier_wait(&start);
    for (f = 0; j->ok && f < FRAMES; ++f) {
        render(f, tex, vbo, pixels);
        if (memcmp(pixels, reference[f], W * H * 4) != 0) {
            ++j->mismatched_frames;
            if (j->first_bad_frame < 0)
                j->first_bad_frame = f;
        }
    }
    if (j->ok) {
        j->error = glGetError();
        if (!j->shared) {
            glDeleteTextures(1, &tex);
            glDeleteBuffers(1, &vbo);
        }
        eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    if (c != EGL_NO_CONTEXT)
        eglDestroyContext(dpy, c);
    if (s != EGL_NO_SURFACE)
        eglDestroySurface(dpy, s);
    free(pixels);
    eglReleaseThread();
    return NULL;
}

int main(void)
{
    static struct job jobs[THREADS];
    GLuint tex, vbo;
    int f, i, same = 1;

    ct_init(W, H);
    dpy = ct.display;
    cfg = ct.config;

    /* The single-threaded reference, in ct's own (unshared) context. */
    tex = make_texture();
    vbo = make_vbo();
    for (f = 0; f < FRAMES; ++f)
        render(f, tex, vbo, reference[f]);
    CHECK_GL(GL_NO_ERROR);
    /* No ct_save: smooth lines, fog and mipmapping differ from Mesa's by more than the
     * differential run allows; what this program checks is equality with itself. */
    /* Frames differ from each other (the scene moves), so a stale frame cannot pass. */
    for (f = 1; f < FRAMES; ++f)
        same = same && memcmp(reference[f], reference[0], sizeof reference[0]) == 0;
    CHECK(!same);

    /* The shared group's objects, made in a context of their own. */
    share_root = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, NULL);
    CHECK(share_root != EGL_NO_CONTEXT);
    CHECK(eglMakeCurrent(dpy, ct.surface, ct.surface, share_root));
    shared_tex = make_texture();
    shared_vbo = make_vbo();
    glFinish();
    CHECK_GL(GL_NO_ERROR);
    /* The root is released: the threads' shared contexts keep the objects alive. */
    CHECK(eglMakeCurrent(dpy, ct.surface, ct.surface, ct.context));

    CHECK(pthread_barrier_init(&start, NULL, THREADS) == 0);
    for (i = 0; i < THREADS; ++i) {
        jobs[i].index = i;
        jobs[i].shared = i % 2 == 0;
        CHECK(pthread_create(&jobs[i].thread, NULL, worker, &jobs[i]) == 0);
    }
    for (i = 0; i < THREADS; ++i)
        CHECK(pthread_join(jobs[i].thread, NULL) == 0);
    pthread_barrier_destroy(&start);

    for (i = 0; i < THREADS; ++i) {
        CHECK(jobs[i].ok);
        CHECK(jobs[i].error == GL_NO_ERROR);
        CHECK(jobs[i].mismatched_frames == 0);
        if (jobs[i].mismatched_frames)
            fprintf(stderr, "thread %d (%s): %d frames differ, first %d\n", i,
                    jobs[i].shared ? "shared" : "unshared", jobs[i].mismatched_frames,
                    jobs[i].first_bad_frame);
    }
    /* The shared objects outlived every thread's context while the root lived. */
    CHECK(eglMakeCurrent(dpy, ct.surface, ct.surface, share_root));
    CHECK(glIsTexture(shared_tex) && glIsBuffer(shared_vbo));
    glDeleteTextures(1, &shared_tex);
    glDeleteBuffers(1, &shared_vbo);
    CHECK_GL(GL_NO_ERROR);
    CHECK(eglMakeCurrent(dpy, ct.surface, ct.surface, ct.context));
    CHECK(eglDestroyContext(dpy, share_root));
    glDeleteTextures(1, &tex);
    glDeleteBuffers(1, &vbo);
    {
        int rc = ct_done(); /* its summary line, then ours last for the harness log */
        printf("%d threads x %d frames, %d sharing objects: identical to the single-threaded run\n",
               THREADS, FRAMES, THREADS / 2);
        return rc;
    }
}
