/*
 * gl_renderbuffer_formats.c: GL_OES_rgb8_rgba8, GL_OES_depth24 and GL_OES_stencil8: the
 * sized renderbuffer formats they add report their sizes, and RGB8, RGBA8 and DEPTH24
 * complete a framebuffer and are rendered into (a depth-tested, scissored draw). A separate
 * stencil attachment is not combined with a depth one here: Mesa reports that framebuffer
 * unsupported (it only pairs them packed), which the extension allows.
 */
#include "common.h"
#include "fbo_functions.h"


static int has_extension(const char *name)
{
    const char *all = (const char *)glGetString(GL_EXTENSIONS);
    size_t n = strlen(name);
    const char *p = all;
    while (p && (p = strstr(p, name)) != NULL) {
        if ((p == all || p[-1] == ' ') && (p[n] == ' ' || p[n] == 0))
            return 1;
        p += n;
    }
    return 0;
}

static GLint rb_param(GLenum pname)
{
    GLint v = -1;
    glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, pname, &v);
    return v;
}

int main(void)
{
    static const GLfloat quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    static const GLenum colors[] = {GL_RGB8_OES, GL_RGBA8_OES};
    GLuint fb, rb[3];
    int k;

    ct_init(8, 8);
    ct_load_fbo();
    CHECK(has_extension("GL_OES_rgb8_rgba8"));
    CHECK(has_extension("GL_OES_depth24"));
    CHECK(has_extension("GL_OES_stencil8"));

    glGenFramebuffersOES(1, &fb);
    glGenRenderbuffersOES(3, rb);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);

    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[1]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_DEPTH_COMPONENT24_OES, 16, 16);
    CHECK(rb_param(GL_RENDERBUFFER_DEPTH_SIZE_OES) == 24);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_DEPTH_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, rb[1]);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[2]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_STENCIL_INDEX8_OES, 16, 16);
    CHECK(rb_param(GL_RENDERBUFFER_STENCIL_SIZE_OES) == 8);
    CHECK(rb_param(GL_RENDERBUFFER_INTERNAL_FORMAT_OES) == GL_STENCIL_INDEX8_OES);
    CHECK_GL(GL_NO_ERROR);

    for (k = 0; k < 2; ++k) {
        glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[0]);
        glRenderbufferStorageOES(GL_RENDERBUFFER_OES, colors[k], 16, 16);
        CHECK_GL(GL_NO_ERROR);
        CHECK(rb_param(GL_RENDERBUFFER_INTERNAL_FORMAT_OES) == (GLint)colors[k]);
        CHECK(rb_param(GL_RENDERBUFFER_RED_SIZE_OES) == 8);
        CHECK(rb_param(GL_RENDERBUFFER_GREEN_SIZE_OES) == 8);
        CHECK(rb_param(GL_RENDERBUFFER_BLUE_SIZE_OES) == 8);
        CHECK(rb_param(GL_RENDERBUFFER_ALPHA_SIZE_OES) == (k == 0 ? 0 : 8));
        glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                     GL_RENDERBUFFER_OES, rb[0]);
        CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);

        glViewport(0, 0, 16, 16);
        glClearColor(0, 0, 0, 0);
        glClearDepthf(1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        /* Depth 0.5 in the right half first; the quad at depth 0.5 then passes GL_LESS only
         * in the left half, which takes 0.2, 0.4, 0.6 (exact in 8 bits). */
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_SCISSOR_TEST);
        glScissor(8, 0, 8, 16);
        glClearDepthf(0.5f);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, quad); /* z = 0: window depth 0.5 */
        glColor4f(0.2f, 0.4f, 0.6f, 1.0f);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glDisable(GL_DEPTH_TEST);
        CHECK_PIXEL(3, 8, 51, 102, 153, 255, 0);
        CHECK_PIXEL(12, 8, 0, 0, 0, k == 0 ? 255 : 0, 0); /* RGB8 reads alpha as 1 */
        CHECK_GL(GL_NO_ERROR);
    }

    /* Formats outside these extensions stay errors. */
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGB, 4, 4);
    CHECK_GL(GL_INVALID_ENUM);

    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glDeleteFramebuffersOES(1, &fb);
    glDeleteRenderbuffersOES(3, rb);
    glViewport(0, 0, 8, 8);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
