/*
 * EGL 1.5 images and EGL_KHR_image_base / EGL_KHR_gl_texture_2D_image with GL_OES_EGL_image:
 * an image made from a level of a GL texture becomes another texture's image
 * (glEGLImageTargetTexture2DOES) and a renderbuffer's storage
 * (glEGLImageTargetRenderbufferStorageOES), with the source's texels; every error of
 * eglCreateImage, eglDestroyImage and the two GL calls.
 * ct:no-diff (Mesa's headless images of a mipmapped texture's level 0 sample as zeros, and
 * Mesa ignores unknown image attributes: CONFORMANCE.md)
 */
#include "common.h"
#include "fbo_functions.h"
#include <EGL/eglext.h>
#include <GLES/glext.h>

static PFNEGLCREATEIMAGEPROC create_image;
static PFNEGLDESTROYIMAGEPROC destroy_image;
static PFNEGLCREATEIMAGEKHRPROC create_image_khr;
static PFNEGLDESTROYIMAGEKHRPROC destroy_image_khr;
static PFNGLEGLIMAGETARGETTEXTURE2DOESPROC image_target_texture;
static PFNGLEGLIMAGETARGETRENDERBUFFERSTORAGEOESPROC image_target_renderbuffer;

static void load(void)
{
    create_image = (PFNEGLCREATEIMAGEPROC)eglGetProcAddress("eglCreateImage");
    destroy_image = (PFNEGLDESTROYIMAGEPROC)eglGetProcAddress("eglDestroyImage");
    create_image_khr = (PFNEGLCREATEIMAGEKHRPROC)eglGetProcAddress("eglCreateImageKHR");
    destroy_image_khr = (PFNEGLDESTROYIMAGEKHRPROC)eglGetProcAddress("eglDestroyImageKHR");
    image_target_texture = (PFNGLEGLIMAGETARGETTEXTURE2DOESPROC)eglGetProcAddress(
        "glEGLImageTargetTexture2DOES");
    image_target_renderbuffer = (PFNGLEGLIMAGETARGETRENDERBUFFERSTORAGEOESPROC)eglGetProcAddress(
        "glEGLImageTargetRenderbufferStorageOES");
    CHECK(create_image && destroy_image && create_image_khr && destroy_image_khr &&
          image_target_texture && image_target_renderbuffer);
    ct_load_fbo();
}

/* A quad over the 8 × 8 surface sampling the bound texture (NEAREST). */
static void textured_quad(void)
{
    static const GLfloat v[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
    static const GLfloat st[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, st);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glDisable(GL_TEXTURE_2D);
}

int main(void)
{
    /* Level 0: red, green / blue, white (bottom row first); level 1: gray. */
    static const GLubyte level0[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                       0, 0, 255, 255, 255, 255, 255, 255};
    static const GLubyte level1[4] = {128, 128, 128, 255};
    static const EGLAttrib level_1[] = {EGL_GL_TEXTURE_LEVEL, 1, EGL_NONE};
    static const EGLAttrib level_5[] = {EGL_GL_TEXTURE_LEVEL, 5, EGL_NONE};
    static const EGLAttrib bad_attr[] = {EGL_WIDTH, 1, EGL_NONE};
    static const EGLint preserved[] = {EGL_IMAGE_PRESERVED_KHR, EGL_TRUE, EGL_NONE};
    GLuint tex[3], fb, rb;
    EGLImage img, img1;
    EGLImageKHR img_khr;
    const char *egl_ext;

    ct_init(8, 8);
    load();
    egl_ext = eglQueryString(ct.display, EGL_EXTENSIONS);
    CHECK(ct_has_word(egl_ext, "EGL_KHR_image_base"));
    CHECK(ct_has_word(egl_ext, "EGL_KHR_gl_texture_2D_image"));
    CHECK(ct_has_word((const char *)glGetString(GL_EXTENSIONS), "GL_OES_EGL_image"));
    glDisable(GL_DITHER);
    glGenTextures(3, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, level0);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, level1);
    CHECK_GL(GL_NO_ERROR);

    img = create_image(ct.display, ct.context, EGL_GL_TEXTURE_2D,
                       (EGLClientBuffer)(uintptr_t)tex[0], NULL);
    CHECK(img != EGL_NO_IMAGE);
    CHECK_EGL(EGL_SUCCESS);
    img1 = create_image(ct.display, ct.context, EGL_GL_TEXTURE_2D,
                        (EGLClientBuffer)(uintptr_t)tex[0], level_1);
    CHECK(img1 != EGL_NO_IMAGE);

    /* Another texture takes the image: the source's texels. */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    image_target_texture(GL_TEXTURE_2D, (GLeglImageOES)img);
    CHECK_GL(GL_NO_ERROR);
    textured_quad();
    CHECK_PIXEL(1, 1, 255, 0, 0, 255, 0);
    CHECK_PIXEL(6, 1, 0, 255, 0, 255, 0);
    CHECK_PIXEL(1, 6, 0, 0, 255, 255, 0);
    CHECK_PIXEL(6, 6, 255, 255, 255, 255, 0);
    /* The level 1 image. */
    image_target_texture(GL_TEXTURE_2D, (GLeglImageOES)img1);
    textured_quad();
    CHECK_PIXEL(3, 3, 128, 128, 128, 255, 0);

    /* A renderbuffer's storage, read back through a framebuffer object. */
    glGenFramebuffersOES(1, &fb);
    glGenRenderbuffersOES(1, &rb);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb);
    image_target_renderbuffer(GL_RENDERBUFFER_OES, (GLeglImageOES)img);
    CHECK_GL(GL_NO_ERROR);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, fb);
    glFramebufferRenderbufferOES(GL_FRAMEBUFFER_OES, GL_COLOR_ATTACHMENT0_OES, GL_RENDERBUFFER_OES,
                             rb);
    CHECK(glCheckFramebufferStatusOES(GL_FRAMEBUFFER_OES) == GL_FRAMEBUFFER_COMPLETE_OES);
    CHECK_PIXEL(0, 0, 255, 0, 0, 255, 0);
    CHECK_PIXEL(1, 1, 255, 255, 255, 255, 0);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);

    /* GL errors: a target the call does not take, a handle that is no image. */
    image_target_texture(GL_TEXTURE_CUBE_MAP_OES, (GLeglImageOES)img);
    CHECK_GL(GL_INVALID_ENUM);
    image_target_renderbuffer(GL_TEXTURE_2D, (GLeglImageOES)img);
    CHECK_GL(GL_INVALID_ENUM);

    /* EGL errors. */
    CHECK(create_image(ct.display, ct.context, EGL_GL_TEXTURE_2D, (EGLClientBuffer)0, NULL) ==
          EGL_NO_IMAGE);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(create_image(ct.display, ct.context, EGL_GL_TEXTURE_2D,
                       (EGLClientBuffer)(uintptr_t)999, NULL) == EGL_NO_IMAGE);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(create_image(ct.display, ct.context, EGL_GL_TEXTURE_2D,
                       (EGLClientBuffer)(uintptr_t)tex[0], level_5) == EGL_NO_IMAGE);
    CHECK_EGL(EGL_BAD_MATCH);
    CHECK(create_image(ct.display, ct.context, EGL_GL_TEXTURE_2D,
                       (EGLClientBuffer)(uintptr_t)tex[0], bad_attr) == EGL_NO_IMAGE);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(create_image(ct.display, ct.context, 0x3333, (EGLClientBuffer)(uintptr_t)tex[0],
                       NULL) == EGL_NO_IMAGE);
    CHECK_EGL(EGL_BAD_PARAMETER);
    CHECK(create_image(ct.display, (EGLContext)(uintptr_t)77, EGL_GL_TEXTURE_2D,
                       (EGLClientBuffer)(uintptr_t)tex[0], NULL) == EGL_NO_IMAGE);
    CHECK_EGL(EGL_BAD_CONTEXT);
    CHECK(create_image(EGL_NO_DISPLAY, ct.context, EGL_GL_TEXTURE_2D,
                       (EGLClientBuffer)(uintptr_t)tex[0], NULL) == EGL_NO_IMAGE);
    CHECK_EGL(EGL_BAD_DISPLAY);

    /* The KHR forms, with an EGLint list. */
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, level1);
    img_khr = create_image_khr(ct.display, ct.context, EGL_GL_TEXTURE_2D_KHR,
                               (EGLClientBuffer)(uintptr_t)tex[2], preserved);
    CHECK(img_khr != EGL_NO_IMAGE_KHR);
    CHECK(destroy_image_khr(ct.display, img_khr));
    CHECK(!destroy_image_khr(ct.display, img_khr));
    CHECK_EGL(EGL_BAD_PARAMETER);

    CHECK(destroy_image(ct.display, img));
    CHECK(destroy_image(ct.display, img1));
    CHECK_EGL(EGL_SUCCESS);
    CHECK(!destroy_image(ct.display, img));
    CHECK_EGL(EGL_BAD_PARAMETER);
    return ct_done();
}
