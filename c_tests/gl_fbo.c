/* OES_framebuffer_object: object names, renderbuffer storage and queries, attachments,
 * completeness, rendering into renderbuffers and textures (and sampling the result), depth
 * and stencil renderbuffers, errors, glGenerateMipmapOES, and renderbuffers shared with a
 * second context of the share group. */
#include "common.h"
#include "fbo_functions.h"

static void quad(float x0, float y0, float x1, float y1)
{
    GLfloat v[8] = {x0, y0, x1, y0, x0, y1, x1, y1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void textured_quad(void)
{
    GLfloat v[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
    GLfloat st[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}

static GLint rb_param(GLenum pname)
{
    GLint v = -1;
    glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, pname, &v);
    return v;
}

static GLint att_param(GLenum attachment, GLenum pname)
{
    GLint v = -1;
    glGetFramebufferAttachmentParameterivOES(GL_FRAMEBUFFER_OES, attachment, pname, &v);
    return v;
}

static GLint get_int(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

static void names_and_queries(void)
{
    GLuint fb[2] = {0, 0}, rb[2] = {0, 0};
    static const GLenum formats[] = {GL_RGBA8_OES, GL_RGB565_OES, GL_RGBA4_OES,
                                     GL_RGB5_A1_OES, GL_DEPTH_COMPONENT16_OES,
                                     GL_DEPTH_COMPONENT24_OES, GL_STENCIL_INDEX8_OES};
    static const GLint sizes[][6] = {{8, 8, 8, 8, 0, 0}, {5, 6, 5, 0, 0, 0},
                                     {4, 4, 4, 4, 0, 0}, {5, 5, 5, 1, 0, 0},
                                     {0, 0, 0, 0, 16, 0}, {0, 0, 0, 0, 24, 0},
                                     {0, 0, 0, 0, 0, 8}};
    unsigned i;

    CHECK(get_int(GL_FRAMEBUFFER_BINDING_OES) == 0);
    CHECK(get_int(GL_RENDERBUFFER_BINDING_OES) == 0);
    CHECK(get_int(GL_MAX_RENDERBUFFER_SIZE_OES) >= 1024);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);

    glGenFramebuffersOES(2, fb);
    glGenRenderbuffersOES(2, rb);
    CHECK(fb[0] != 0 && fb[1] != 0 && fb[0] != fb[1]);
    CHECK(rb[0] != 0 && rb[1] != 0 && rb[0] != rb[1]);
    /* Generated names become objects when first bound. */
    CHECK(!glIsFramebufferOES(fb[0]));
    CHECK(!glIsRenderbufferOES(rb[0]));
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb[0]);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[0]);
    CHECK(glIsFramebufferOES(fb[0]));
    CHECK(glIsRenderbufferOES(rb[0]));
    CHECK(!glIsFramebufferOES(0) && !glIsRenderbufferOES(0));
    CHECK(get_int(GL_FRAMEBUFFER_BINDING_OES) == (GLint)fb[0]);
    CHECK(get_int(GL_RENDERBUFFER_BINDING_OES) == (GLint)rb[0]);
    CHECK_GL(GL_NO_ERROR);

    /* Initial renderbuffer state. */
    CHECK(rb_param(GL_RENDERBUFFER_WIDTH_OES) == 0);
    CHECK(rb_param(GL_RENDERBUFFER_HEIGHT_OES) == 0);
    CHECK_MESA_DEVIATES(rb_param(GL_RENDERBUFFER_INTERNAL_FORMAT_OES) == GL_RGBA4_OES,
                        "Mesa reports GL_RGBA");
    CHECK_GL(GL_NO_ERROR);

    for (i = 0; i < sizeof formats / sizeof formats[0]; ++i) {
        glRenderbufferStorageOES(GL_RENDERBUFFER_OES, formats[i], 8, 4);
        CHECK_GL(GL_NO_ERROR);
        CHECK(rb_param(GL_RENDERBUFFER_WIDTH_OES) == 8);
        CHECK(rb_param(GL_RENDERBUFFER_HEIGHT_OES) == 4);
        CHECK(rb_param(GL_RENDERBUFFER_INTERNAL_FORMAT_OES) == (GLint)formats[i]);
        /* Mesa may store a format with more bits than asked for; the sizes are ours. */
        if (ct_strict()) {
            CHECK(rb_param(GL_RENDERBUFFER_RED_SIZE_OES) == sizes[i][0]);
            CHECK(rb_param(GL_RENDERBUFFER_GREEN_SIZE_OES) == sizes[i][1]);
            CHECK(rb_param(GL_RENDERBUFFER_BLUE_SIZE_OES) == sizes[i][2]);
            CHECK(rb_param(GL_RENDERBUFFER_ALPHA_SIZE_OES) == sizes[i][3]);
            CHECK(rb_param(GL_RENDERBUFFER_DEPTH_SIZE_OES) == sizes[i][4]);
            CHECK(rb_param(GL_RENDERBUFFER_STENCIL_SIZE_OES) == sizes[i][5]);
        } else {
            CHECK((rb_param(GL_RENDERBUFFER_RED_SIZE_OES) > 0) == (sizes[i][0] > 0));
            CHECK((rb_param(GL_RENDERBUFFER_DEPTH_SIZE_OES) > 0) == (sizes[i][4] > 0));
            CHECK((rb_param(GL_RENDERBUFFER_STENCIL_SIZE_OES) > 0) == (sizes[i][5] > 0));
        }
    }

    /* Errors. */
    glRenderbufferStorageOES(GL_FRAMEBUFFER_OES, GL_RGBA4_OES, 4, 4);
    CHECK_GL(GL_INVALID_ENUM);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA, 4, 4);
    CHECK_GL(GL_INVALID_ENUM);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA4_OES, -1, 4);
    CHECK_GL(GL_INVALID_VALUE);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA4_OES, 4,
                             get_int(GL_MAX_RENDERBUFFER_SIZE_OES) + 1);
    CHECK_GL(GL_INVALID_VALUE);
    glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, GL_TEXTURE_2D, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glBindRenderbufferOES(GL_FRAMEBUFFER_OES, rb[1]);
    CHECK_GL(GL_INVALID_ENUM);
    glBindFramebufferOES(GL_RENDERBUFFER_OES, fb[1]);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(glCheckFramebufferStatusOES(GL_RENDERBUFFER_OES) == 0);
    CHECK_GL(GL_INVALID_ENUM);
    glGenFramebuffersOES(-1, fb);
    CHECK_GL(GL_INVALID_VALUE);
    glGenRenderbuffersOES(-1, rb);
    CHECK_GL(GL_INVALID_VALUE);
    glDeleteFramebuffersOES(-1, fb);
    CHECK_GL(GL_INVALID_VALUE);
    glDeleteRenderbuffersOES(-1, rb);
    CHECK_GL(GL_INVALID_VALUE);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_TEXTURE_2D, GL_RENDERBUFFER_OES, rb[0]);
    CHECK_GL(GL_INVALID_ENUM);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D,
                                 rb[0]);
    CHECK_GL(GL_INVALID_ENUM);
    glFramebufferRenderbufferOES(GL_RENDERBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, rb[0]);
    CHECK_GL(GL_INVALID_ENUM);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, 4242);
    CHECK_GL(GL_INVALID_OPERATION);
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D, 4242,
                              0);
    CHECK_GL(GL_INVALID_OPERATION);
    glGetFramebufferAttachmentParameterivOES(GL_FRAMEBUFFER_OES, GL_TEXTURE_2D,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glGenerateMipmapOES(GL_RENDERBUFFER_OES);
    CHECK_GL(GL_INVALID_ENUM);

    /* Nothing attached: incomplete, and drawing says so. */
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) ==
          GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_OES);
    CHECK(att_param(GL_COLOR_ATTACHMENT0_OES, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES) ==
          GL_NONE_OES);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_GL(GL_INVALID_FRAMEBUFFER_OPERATION_OES);
    quad(-1, -1, 1, 1);
    CHECK_GL(GL_INVALID_FRAMEBUFFER_OPERATION_OES);

    /* Attachment queries. */
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[0]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGB565_OES, 4, 4);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, rb[0]);
    CHECK_GL(GL_NO_ERROR);
    CHECK(att_param(GL_COLOR_ATTACHMENT0_OES, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES) ==
          GL_RENDERBUFFER_OES);
    CHECK(att_param(GL_COLOR_ATTACHMENT0_OES, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES) ==
          (GLint)rb[0]);
    att_param(GL_COLOR_ATTACHMENT0_OES, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_OES);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);

    /* A color renderbuffer at the depth attachment is not attachment complete. */
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_DEPTH_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, rb[0]);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) ==
          GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES);
    /* A depth buffer of another size: dimensions. */
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[1]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_DEPTH_COMPONENT16_OES, 8, 8);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_DEPTH_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, rb[1]);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) ==
          GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_OES);
    /* Zero-sized storage: attachment incomplete. */
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_DEPTH_COMPONENT16_OES, 0, 0);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) ==
          GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_DEPTH_COMPONENT16_OES, 4, 4);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    CHECK_GL(GL_NO_ERROR);

    /* Deleting an attached renderbuffer detaches it from the bound framebuffer. */
    glDeleteRenderbuffersOES(1, &rb[1]);
    CHECK(att_param(GL_DEPTH_ATTACHMENT_OES, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES) ==
          GL_NONE_OES);
    CHECK(!glIsRenderbufferOES(rb[1]));
    CHECK(get_int(GL_RENDERBUFFER_BINDING_OES) == 0);
    glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, GL_RENDERBUFFER_WIDTH_OES, NULL);
    CHECK_GL(GL_INVALID_OPERATION); /* renderbuffer 0 bound */
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA4_OES, 4, 4);
    CHECK_GL(GL_INVALID_OPERATION);

    /* Deleting the bound framebuffer binds 0. */
    glDeleteFramebuffersOES(2, fb);
    CHECK(get_int(GL_FRAMEBUFFER_BINDING_OES) == 0);
    CHECK(!glIsFramebufferOES(fb[0]));
    glDeleteRenderbuffersOES(1, &rb[0]);
    CHECK_GL(GL_NO_ERROR);

    /* With the window-system framebuffer bound, attachments cannot change. */
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, 0);
    CHECK_GL(GL_INVALID_OPERATION);
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D, 0, 0);
    CHECK_GL(GL_INVALID_OPERATION);
    glGetFramebufferAttachmentParameterivOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES, NULL);
    CHECK_GL(GL_INVALID_OPERATION);
}

/* Renderbuffers: clear, draw with depth and stencil, read back. */
static void render_to_renderbuffers(void)
{
    GLuint fb = 0, rb[3] = {0, 0, 0};
    GLushort px565 = 0;

    glGenFramebuffersOES(1, &fb);
    glGenRenderbuffersOES(3, rb);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[0]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA8_OES, 16, 8);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[1]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_DEPTH_COMPONENT16_OES, 16, 8);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[2]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_STENCIL_INDEX8_OES, 16, 8);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, rb[0]);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_DEPTH_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, rb[1]);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    CHECK_GL(GL_NO_ERROR);
    CHECK(get_int(GL_RED_BITS) == 8);
    CHECK(get_int(GL_DEPTH_BITS) == 16);

    glViewport(0, 0, 16, 8);
    glClearColor(0, 0, 1, 1);
    glClearDepthf(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    CHECK_PIXEL(0, 0, 0, 0, 255, 255, 0);
    CHECK_PIXEL(15, 7, 0, 0, 255, 255, 0);

    /* Depth test against the depth renderbuffer: a near red quad on the left, then a far
     * green quad over everything only lands on the right. */
    glEnable(GL_DEPTH_TEST);
    glColor4f(1, 0, 0, 1);
    glPushMatrix();
    glTranslatef(0, 0, -0.5f); /* z = -0.5: nearer */
    quad(-1, -1, 0, 1);
    glPopMatrix();
    glColor4f(0, 1, 0, 1);
    quad(-1, -1, 1, 1); /* z = 0 */
    glDisable(GL_DEPTH_TEST);
    CHECK_PIXEL(2, 4, 255, 0, 0, 255, 0);
    CHECK_PIXEL(12, 4, 0, 255, 0, 255, 0);
    CHECK_GL(GL_NO_ERROR);

    /* Stencil: add the stencil buffer, mark the left half, draw where it is marked. */
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_STENCIL_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, rb[2]);
    /* Separate depth and stencil renderbuffers: complete here; Mesa answers
     * GL_FRAMEBUFFER_UNSUPPORTED_OES (allowed: an implementation-dependent restriction). */
    CHECK_MESA_DEVIATES(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) ==
                            GL_FRAMEBUFFER_COMPLETE_OES,
                        "Mesa: unsupported combination");
    if (glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES) {
        CHECK(get_int(GL_STENCIL_BITS) == 8);
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 1, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glColorMask(0, 0, 0, 0);
        quad(-1, -1, 0, 1);
        glColorMask(1, 1, 1, 1);
        glStencilFunc(GL_EQUAL, 1, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glColor4f(1, 1, 1, 1);
        quad(-1, -1, 1, 1);
        glDisable(GL_STENCIL_TEST);
        CHECK_PIXEL(2, 4, 255, 255, 255, 255, 0);
        CHECK_PIXEL(12, 4, 0, 255, 0, 255, 0);
    } else {
        /* Mesa may not support a separate stencil renderbuffer with a separate depth one. */
        glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_STENCIL_ATTACHMENT_OES,
                                     GL_RENDERBUFFER_OES, 0);
    }
    CHECK_GL(GL_NO_ERROR);

    /* Rebinding keeps the contents (they landed in the renderbuffers). */
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    CHECK_PIXEL(12, 4, 0, 255, 0, 255, 0);

    /* An RGB565 color buffer: the implementation read format follows it. */
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb[0]);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGB565_OES, 16, 8);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_STENCIL_ATTACHMENT_OES,
                                 GL_RENDERBUFFER_OES, 0);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK(get_int(GL_RED_BITS) == 5 && get_int(GL_GREEN_BITS) == 6);
    CHECK(get_int(GL_ALPHA_BITS) == 0);
    if (get_int(GL_IMPLEMENTATION_COLOR_READ_TYPE_OES) == GL_UNSIGNED_SHORT_5_6_5) {
        glReadPixels(3, 3, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &px565);
        CHECK(px565 == 0xf800);
    }
    CHECK_PIXEL(3, 3, 255, 0, 0, 255, 0);
    CHECK_GL(GL_NO_ERROR);

    /* RGBA4 and RGB5_A1: clears quantize to the format. */
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA4_OES, 16, 8);
    glClearColor(1, 0.5f, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(3, 3, 255, 136, 0, 255, 0); /* 0.5 * 15 rounds to 8: 0x88 */
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGB5_A1_OES, 16, 8);
    glClearColor(0, 1, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(3, 3, 0, 255, 0, 0, 0);
    CHECK_GL(GL_NO_ERROR);

    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glDeleteFramebuffersOES(1, &fb);
    glDeleteRenderbuffersOES(3, rb);
    glViewport(0, 0, ct.width, ct.height);
}

/* A texture as the color attachment: render into it, then sample it. */
static void render_to_texture(void)
{
    GLuint fb = 0, tex = 0, lum = 0;
    GLubyte texels[4 * 8 * 8];

    memset(texels, 0x40, sizeof texels);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);

    glGenFramebuffersOES(1, &fb);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    /* OES_fbo_render_mipmap: any level up to log2 of the largest texture size; level 1
     * has no image yet, so the framebuffer is incomplete. */
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D, tex,
                              1);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) ==
          GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES);
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D, tex,
                              -1);
    CHECK_GL(GL_INVALID_VALUE);
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                              GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES, tex, 0);
    CHECK_GL(GL_INVALID_OPERATION); /* not a cube map */
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D, tex,
                              0);
    CHECK_GL(GL_NO_ERROR);
    CHECK(att_param(GL_COLOR_ATTACHMENT0_OES, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES) ==
          GL_TEXTURE);
    CHECK(att_param(GL_COLOR_ATTACHMENT0_OES, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_OES) ==
          (GLint)tex);
    CHECK(att_param(GL_COLOR_ATTACHMENT0_OES, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_OES) == 0);
    CHECK(att_param(GL_COLOR_ATTACHMENT0_OES,
                    GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_OES) == 0);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    CHECK_GL(GL_NO_ERROR);

    /* The texture's contents are there before any rendering. */
    glViewport(0, 0, 8, 8);
    CHECK_PIXEL(5, 5, 0x40, 0x40, 0x40, 0x40, 0);
    /* Left half red, right half blue, top-right quarter green. */
    glColor4f(1, 0, 0, 1);
    quad(-1, -1, 0, 1);
    glColor4f(0, 0, 1, 1);
    quad(0, -1, 1, 1);
    glColor4f(0, 1, 0, 1);
    quad(0, 0, 1, 1);
    CHECK_PIXEL(1, 1, 255, 0, 0, 255, 0);
    CHECK_PIXEL(6, 1, 0, 0, 255, 255, 0);
    CHECK_PIXEL(6, 6, 0, 255, 0, 255, 0);

    /* Back to the surface: sample the texture over the whole surface. */
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glViewport(0, 0, ct.width, ct.height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    textured_quad();
    CHECK_PIXEL(4, 4, 255, 0, 0, 255, 0);
    CHECK_PIXEL(ct.width - 4, 4, 0, 0, 255, 255, 0);
    CHECK_PIXEL(ct.width - 4, ct.height - 4, 0, 255, 0, 255, 0);
    CHECK_PIXEL(4, ct.height - 4, 255, 0, 0, 255, 0);
    ct_save("fbo_texture_sampled");
    glDisable(GL_TEXTURE_2D);
    CHECK_GL(GL_NO_ERROR);

    /* glGenerateMipmapOES builds the chain from the rendered level. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glGenerateMipmapOES(GL_TEXTURE_2D);
    CHECK_GL(GL_NO_ERROR);
    glEnable(GL_TEXTURE_2D);
    {
        /* A quad 1 pixel wide samples level 3 (1 × 1): the mean of the rendered image. */
        GLfloat v[8] = {-1, -1, -1 + 2.0f / ct.width, -1, -1, -1 + 2.0f / ct.height,
                        -1 + 2.0f / ct.width, -1 + 2.0f / ct.height};
        GLfloat st[8] = {0, 0, 1, 0, 0, 1, 1, 1};
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, v);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(2, GL_FLOAT, 0, st);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        /* Half red, a quarter blue, a quarter green. */
        CHECK_PIXEL(0, 0, 128, 64, 64, 255, 2);
    }
    glDisable(GL_TEXTURE_2D);

    /* Rendering into the texture after it was sampled: the new contents are sampled next. */
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glViewport(0, 0, 8, 8);
    glClearColor(1, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glViewport(0, 0, ct.width, ct.height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    textured_quad();
    glDisable(GL_TEXTURE_2D);
    CHECK_PIXEL(10, 10, 255, 255, 0, 255, 0);

    /* A texture redefined while attached: the framebuffer follows its new size. */
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    glClearColor(0, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK_PIXEL(3, 3, 0, 255, 255, 255, 0);
    CHECK(get_int(GL_ALPHA_BITS) == 0);
    /* glCopyTexImage2D from the framebuffer object. */
    glGenTextures(1, &lum);
    glBindTexture(GL_TEXTURE_2D, lum);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 0);
    CHECK_GL(GL_NO_ERROR);

    /* A luminance texture is not color-renderable here. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 4, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE,
                 texels);
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D, lum,
                              0);
    CHECK_MESA_DEVIATES(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) ==
                            GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_OES,
                        "Mesa renders into luminance textures");
    /* Deleting an attached texture detaches it. */
    glDeleteTextures(1, &lum);
    CHECK(att_param(GL_COLOR_ATTACHMENT0_OES, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_OES) ==
          GL_NONE_OES);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    CHECK_GL(GL_INVALID_FRAMEBUFFER_OPERATION_OES);

    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glDeleteFramebuffersOES(1, &fb);
    glDeleteTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, 0);
    glViewport(0, 0, ct.width, ct.height);
    CHECK_GL(GL_NO_ERROR);
}

/* Renderbuffers are shared with the share group; framebuffer objects are not. */
static void sharing(void)
{
    GLuint fb = 0, rb = 0;
    EGLContext other;

    glGenRenderbuffersOES(1, &rb);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb);
    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGBA8_OES, 4, 4);
    glGenFramebuffersOES(1, &fb);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                 GL_RENDERBUFFER_OES, rb);
    glViewport(0, 0, 4, 4);
    glClearColor(1, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    CHECK_GL(GL_NO_ERROR);

    other = eglCreateContext(ct.display, ct.config, ct.context, NULL);
    CHECK(other != EGL_NO_CONTEXT);
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, other));
    CHECK(glIsRenderbufferOES(rb));
    /* Framebuffer objects are per context (OES_framebuffer_object); Mesa shares them. */
    CHECK_MESA_DEVIATES(!glIsFramebufferOES(fb), "Mesa shares framebuffer objects");
    {
        GLuint fb2 = 0;
        glGenFramebuffersOES(1, &fb2);
        glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb2);
        glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES,
                                     GL_RENDERBUFFER_OES, rb);
        CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
        CHECK_PIXEL(1, 1, 255, 0, 255, 255, 0);
        glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
        glDeleteFramebuffersOES(1, &fb2);
    }
    CHECK_GL(GL_NO_ERROR);
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    eglDestroyContext(ct.display, other);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glDeleteFramebuffersOES(1, &fb);
    glDeleteRenderbuffersOES(1, &rb);
    glViewport(0, 0, ct.width, ct.height);
    CHECK_GL(GL_NO_ERROR);
}

/* OES_fbo_render_mipmap: rendering into level 1 of a texture, then sampling that level. */
static void render_to_mipmap_level(void)
{
    GLuint tex, fb;
    int level;

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    for (level = 0; level <= 3; ++level) /* 8x8 down to 1x1, all black */
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, 8 >> level, 8 >> level, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffersOES(1, &fb);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glFramebufferTexture2DOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_TEXTURE_2D, tex,
                              1);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    glViewport(0, 0, 4, 4);
    glClearColor(0, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glViewport(0, 0, ct.width, ct.height);
    CHECK_GL(GL_NO_ERROR);

    /* A 4x4 quad samples level 1 (8x8 texels onto 4x4 pixels). */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glViewport(0, 0, 4, 4);
    textured_quad();
    glViewport(0, 0, ct.width, ct.height);
    glDisable(GL_TEXTURE_2D);
    CHECK_PIXEL(1, 1, 0, 255, 255, 255, 0);
    glDeleteFramebuffersOES(1, &fb);
    glDeleteTextures(1, &tex);
    CHECK_GL(GL_NO_ERROR);
}

int main(void)
{
    ct_init(32, 32);
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_framebuffer_object") != NULL);
    if (!ct_load_fbo())
        return ct_done();
    names_and_queries();
    render_to_renderbuffers();
    render_to_texture();
    sharing();
    render_to_mipmap_level();
    return ct_done();
}
