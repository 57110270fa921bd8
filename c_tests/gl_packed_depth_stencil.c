/*
 * GL_OES_packed_depth_stencil: a DEPTH24_STENCIL8 renderbuffer reports 24 depth and 8
 * stencil bits, attached to both the depth and the stencil point completes a framebuffer,
 * and both tests work on it: a stencil mask written by a first quad and a depth value
 * written by it limit a second one.
 */
#include "common.h"
#include "fbo_functions.h"


static GLint rb_param(GLenum pname)
{
    GLint v = -1;
    glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, pname, &v);
    return v;
}

/* A quad over x in [x0, x1] of clip space at depth z, in the current color. */
static void quad(GLfloat x0, GLfloat x1, GLfloat z)
{
    GLfloat v[12];
    v[0] = x0, v[1] = -1, v[2] = z;
    v[3] = x1, v[4] = -1, v[5] = z;
    v[6] = x0, v[7] = 1, v[8] = z;
    v[9] = x1, v[10] = 1, v[11] = z;
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

int main(void)
{
    GLuint fb, rb[2];

    ct_init(8, 8);
    ct_load_fbo();
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_packed_depth_stencil") !=
          NULL);
    if (!glCheckFramebufferStatusOES)
        return ct_done();

    glGenFramebuffersOES(1, &fb);
    glGenRenderbuffersOES(2, rb);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[0]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA8_OES, 8, 8);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, rb[0]);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[1]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_DEPTH24_STENCIL8_OES, 8, 8);
    CHECK_GL(GL_NO_ERROR);
    CHECK(rb_param(GL_RENDERBUFFER_INTERNAL_FORMAT_OES) == GL_DEPTH24_STENCIL8_OES);
    CHECK(rb_param(GL_RENDERBUFFER_DEPTH_SIZE_OES) == 24);
    CHECK(rb_param(GL_RENDERBUFFER_STENCIL_SIZE_OES) == 8);
    CHECK(rb_param(GL_RENDERBUFFER_RED_SIZE_OES) == 0);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_DEPTH_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, rb[1]);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_STENCIL_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, rb[1]);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    CHECK_GL(GL_NO_ERROR);
    {
        GLint depth_bits = 0, stencil_bits = 0;
        glGetIntegerv(GL_DEPTH_BITS, &depth_bits);
        glGetIntegerv(GL_STENCIL_BITS, &stencil_bits);
        CHECK(depth_bits == 24 && stencil_bits == 8);
    }

    /* The left half: stencil 1 and depth 0.5 (z = 0), in blue. */
    glClearColor(0, 0, 0, 1);
    glClearDepthf(1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor4f(0, 0, 1, 1);
    quad(-1, 0, 0);
    /* Red everywhere where the stencil is 1 and in front of the first quad: the left
     * half. Green behind it (z = 0.5) where the stencil is 1: nowhere. */
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColor4f(1, 0, 0, 1);
    quad(-1, 1, -0.5f);
    glColor4f(0, 1, 0, 1);
    quad(-1, 1, 0.5f);
    CHECK_PIXEL(1, 4, 255, 0, 0, 255, 0);
    CHECK_PIXEL(6, 4, 0, 0, 0, 255, 0);
    CHECK_GL(GL_NO_ERROR);
    ct_save("packed");
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);

    /* Attached to the stencil point alone, it completes a framebuffer too. */
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_DEPTH_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, 0);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);

    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glDeleteFramebuffersOES(1, &fb);
    glDeleteRenderbuffersOES(2, rb);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
