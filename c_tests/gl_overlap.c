/*
 * gl_overlap.c: a scene long enough that the library hands full batches of primitives to
 * its worker threads while the program goes on drawing (rasterization overlapped with the
 * next draws). Checked: the image is the same with GLES_CM_THREADS 1, 2 and 4 and the same
 * as when every draw is finished at once with glFinish; a glClear, a glReadPixels and
 * format queries (GL_RED_BITS, GL_STENCIL_BITS, the stencil reference clamp) in the middle
 * of the scene see and keep the recorded order. Without a depth test each pixel shows the
 * last triangle over it, so a batch landing early or late changes the image.
 *
 * ct:no-diff (every check compares this library with itself; the saved image is a dithered
 * RGB565 one, whose dither pattern is the implementation's choice)
 */
#define _POSIX_C_SOURCE 200809L
#include "common.h"
#include "child_hash.h"

#define W 96
#define H 80
#define DRAWS 40
#define TRIS 300

static const EGLint rgb565[] = {
    EGL_RED_SIZE, 5, EGL_GREEN_SIZE, 6, EGL_BLUE_SIZE, 5, EGL_ALPHA_SIZE, 0,
    EGL_DEPTH_SIZE, 16, EGL_STENCIL_SIZE, 8, EGL_NONE,
};

static uint32_t next(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* The scene; with finish_each, glFinish after every draw. Returns 0 when a query in the
 * middle of the scene gave a wrong answer. */
static int scene(int finish_each)
{
    static GLfloat v[TRIS * 9];
    static GLubyte c[TRIS * 12];
    uint32_t s = 777;
    GLint red = 0, stencil = 0, ref = 0;
    GLubyte probe[4];
    int d, k, ok = 1;

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.2f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    glShadeModel(GL_SMOOTH);
    for (d = 0; d < DRAWS; ++d) {
        for (k = 0; k < TRIS * 3; ++k) {
            v[3 * k] = (GLfloat)(next(&s) % 12000) / 100.0f - 12;
            v[3 * k + 1] = (GLfloat)(next(&s) % 10000) / 100.0f - 10;
            v[3 * k + 2] = 0;
        }
        for (k = 0; k < TRIS * 12; ++k)
            c[k] = (GLubyte)next(&s);
        /* Flat shading for half the draws: the provoking vertex's color. */
        glShadeModel(d % 2 ? GL_FLAT : GL_SMOOTH);
        glDrawArrays(GL_TRIANGLES, 0, TRIS * 3);
        if (finish_each)
            glFinish();
        if (d == 10) {
            /* Part of the screen cleared between draws: after draw 10, before draw 11. */
            glEnable(GL_SCISSOR_TEST);
            glScissor(10, 10, 40, 30);
            glClearColor(1, 1, 0, 1);
            glClear(GL_COLOR_BUFFER_BIT);
            glDisable(GL_SCISSOR_TEST);
        }
        if (d == 20) {
            glGetIntegerv(GL_RED_BITS, &red);
            glGetIntegerv(GL_STENCIL_BITS, &stencil);
            glStencilFunc(GL_ALWAYS, 1000, 0xff);
            glGetIntegerv(GL_STENCIL_REF, &ref);
            ok = ok && red == 5 && stencil == 8 && ref == 255;
        }
        if (d == 25) {
            glReadPixels(W / 2, H / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, probe);
        }
    }
    glDisableClientState(GL_COLOR_ARRAY);
    return ok && glGetError() == GL_NO_ERROR;
}

/* FNV-1a of the final image; 0 when anything failed. */
static uint64_t image_hash(int finish_each)
{
    static GLubyte px[W * H * 4];
    size_t i;
    int distinct = 0;
    if (!scene(finish_each))
        return 0;
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (i = 4; i < sizeof px; ++i)
        distinct += px[i] != px[i % 4];
    /* Something was drawn: not one color everywhere. */
    return distinct > 0 ? ct_fnv1a(1469598103934665603ull, px, sizeof px) : 0;
}

/* The scene in a child process (ct_child_hash), batches behind. */
static uint64_t child_scene(void)
{
    ct_init_config(W, H, rgb565);
    return image_hash(0);
}

int main(void)
{
    /* Before anything starts the library in this process: children with their own
     * thread counts. */
    uint64_t h1 = ct_child_hash("1", child_scene), h2 = ct_child_hash("2", child_scene),
             h4 = ct_child_hash("4", child_scene);
    CHECK(h1 != 0);
    CHECK(h1 == h2 && h1 == h4);
    ct_init_config(W, H, rgb565);
    CHECK(image_hash(1) == h1);
    /* The same scene again, batches behind, in the same process. */
    CHECK(image_hash(0) == h1);
    ct_save("overlap");
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
