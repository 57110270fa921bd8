/*
 * Render to texture through eglBindTexImage (EGL 1.4 §3.6): a pbuffer created with
 * EGL_TEXTURE_FORMAT/EGL_TEXTURE_TARGET is rendered into with its own context, bound as the
 * image of the texture object current in a second context on another pbuffer, and sampled
 * with NEAREST at 1:1, so every texel lands exactly. Also: eglReleaseTexImage, binding twice
 * (EGL_BAD_ACCESS), a bad buffer (EGL_BAD_PARAMETER) and a pbuffer without a texture format
 * (EGL_BAD_MATCH). Then a 300 × 300 pbuffer (not a power of two, as in Mesa's bindtex demo)
 * bound the same way and drawn 1:1 with NEAREST and with LINEAR under REPEAT: every texel
 * must land on its own pixel (GL_OES_texture_npot).
 *
 * ct:no-diff (Mesa's headless eglBindTexImage succeeds but the texture samples as zeros,
 * on llvmpipe and softpipe alike, measured with Mesa 22.3)
 */
#include "common.h"

static void quad(void);

/* The 300 × 300 image: a grid of cells of uneven sizes, each its own color. */
static const int cell_x[] = {0, 37, 101, 150, 233, 300};
static const int cell_y[] = {0, 61, 149, 222, 300};

static int cell_of(const int *edges, int v)
{
    int k = 0;
    while (v >= edges[k + 1])
        ++k;
    return k;
}

static void npot_surface(void)
{
    static const EGLint big_tex[] = {EGL_WIDTH, 300, EGL_HEIGHT, 300, EGL_TEXTURE_FORMAT,
                                     EGL_TEXTURE_RGBA, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D,
                                     EGL_NONE};
    static const EGLint big_plain[] = {EGL_WIDTH, 300, EGL_HEIGHT, 300, EGL_NONE};
    static GLubyte px[300 * 300 * 4];
    EGLSurface src = eglCreatePbufferSurface(ct.display, ct.config, big_tex);
    EGLSurface dst = eglCreatePbufferSurface(ct.display, ct.config, big_plain);
    GLuint tex = 0;
    int i, j, x, y, pass;
    CHECK(src != EGL_NO_SURFACE && dst != EGL_NO_SURFACE);
    CHECK(eglMakeCurrent(ct.display, src, src, ct.context));
    glViewport(0, 0, 300, 300);
    glEnable(GL_SCISSOR_TEST);
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 5; ++i) {
            glScissor(cell_x[i], cell_y[j], cell_x[i + 1] - cell_x[i], cell_y[j + 1] - cell_y[j]);
            glClearColor(i * 50 / 255.0f, j * 60 / 255.0f, 128 / 255.0f, 1);
            glClear(GL_COLOR_BUFFER_BIT);
        }
    glDisable(GL_SCISSOR_TEST);
    CHECK(eglMakeCurrent(ct.display, dst, dst, ct.context));
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    CHECK(eglBindTexImage(ct.display, src, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_SUCCESS);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (pass = 0; pass < 2; ++pass) {
        GLint filter = pass == 0 ? GL_NEAREST : GL_LINEAR;
        int bad = 0;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        quad();
        glReadPixels(0, 0, 300, 300, GL_RGBA, GL_UNSIGNED_BYTE, px);
        for (y = 0; y < 300; ++y)
            for (x = 0; x < 300; ++x) {
                const GLubyte *p = px + (y * 300 + x) * 4;
                int ci = cell_of(cell_x, x), cj = cell_of(cell_y, y);
                if (p[0] != ci * 50 || p[1] != cj * 60 || p[2] != 128 || p[3] != 255) {
                    if (bad++ < 4)
                        fprintf(stderr, "300x300 %s: pixel (%d, %d) is (%d, %d, %d, %d)\n",
                                pass == 0 ? "NEAREST" : "LINEAR", x, y, p[0], p[1], p[2],
                                p[3]);
                }
            }
        CHECK(bad == 0);
    }
    CHECK_GL(GL_NO_ERROR);
    ct_save("npot_300");
    CHECK(eglReleaseTexImage(ct.display, src, EGL_BACK_BUFFER));
    glDeleteTextures(1, &tex);
    glDisable(GL_TEXTURE_2D);
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    eglDestroySurface(ct.display, src);
    eglDestroySurface(ct.display, dst);
    CHECK_EGL(EGL_SUCCESS);
}

static void quad(void)
{
    static const GLfloat v[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
    static const GLfloat t[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glTexCoordPointer(2, GL_FLOAT, 0, t);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
}

int main(void)
{
    static const EGLint tex_attribs[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_TEXTURE_FORMAT,
                                         EGL_TEXTURE_RGBA, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D,
                                         EGL_NONE};
    static const EGLint plain_attribs[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
    EGLSurface tex_surface, plain;
    EGLContext tex_ctx;
    GLuint tex = 0;
    EGLint value = 0;

    ct_init(8, 8); /* the sampling side: ct.surface / ct.context */
    CHECK(eglGetConfigAttrib(ct.display, ct.config, EGL_BIND_TO_TEXTURE_RGBA, &value));
    CHECK(value == EGL_TRUE);

    /* The texture side: its own pbuffer and context, left half red, right half blue. */
    tex_surface = eglCreatePbufferSurface(ct.display, ct.config, tex_attribs);
    tex_ctx = eglCreateContext(ct.display, ct.config, EGL_NO_CONTEXT, NULL);
    CHECK(tex_surface != EGL_NO_SURFACE && tex_ctx != EGL_NO_CONTEXT);
    CHECK(eglQuerySurface(ct.display, tex_surface, EGL_TEXTURE_FORMAT, &value) &&
          value == EGL_TEXTURE_RGBA);
    CHECK(eglMakeCurrent(ct.display, tex_surface, tex_surface, tex_ctx));
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 4, 8);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);

    /* Bind it as the texture of the sampling context. */
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    CHECK(eglBindTexImage(ct.display, tex_surface, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_SUCCESS);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    quad();
    CHECK_PIXEL(0, 0, 255, 0, 0, 255, 0);
    CHECK_PIXEL(3, 7, 255, 0, 0, 255, 0);
    CHECK_PIXEL(4, 0, 0, 0, 255, 255, 0);
    CHECK_PIXEL(7, 7, 0, 0, 255, 255, 0);
    CHECK_GL(GL_NO_ERROR);
    ct_save("sampled");

    /* Bound already: EGL_BAD_ACCESS. A buffer other than the back buffer: EGL_BAD_PARAMETER
     * (EGL 1.4 §3.6.1; the reference pages say EGL_BAD_MATCH). */
    CHECK(!eglBindTexImage(ct.display, tex_surface, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_BAD_ACCESS);
    CHECK(!eglReleaseTexImage(ct.display, tex_surface, EGL_BACK_BUFFER + 1));
    CHECK_EGL(EGL_BAD_PARAMETER);

    /* Released, the texture has no image: the unit is off and the fragment keeps the
     * primary color (the current color, white). */
    CHECK(eglReleaseTexImage(ct.display, tex_surface, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_SUCCESS);
    glClear(GL_COLOR_BUFFER_BIT);
    quad();
    CHECK_PIXEL(2, 2, 255, 255, 255, 255, 0);

    /* A pbuffer without a texture format cannot be bound. */
    plain = eglCreatePbufferSurface(ct.display, ct.config, plain_attribs);
    CHECK(plain != EGL_NO_SURFACE);
    CHECK(!eglBindTexImage(ct.display, plain, EGL_BACK_BUFFER));
    CHECK_EGL(EGL_BAD_MATCH);

    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &tex);
    npot_surface();
    eglDestroySurface(ct.display, plain);
    eglDestroySurface(ct.display, tex_surface);
    eglDestroyContext(ct.display, tex_ctx);
    CHECK_EGL(EGL_SUCCESS);
    return ct_done();
}
