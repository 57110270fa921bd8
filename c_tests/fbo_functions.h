/*
 * OES_framebuffer_object's functions through eglGetProcAddress (Mesa exports them only that
 * way), under their standard names, for the programs that use framebuffer objects.
 * Include after common.h; call ct_load_fbo() once a context is current.
 */
#ifndef CT_FBO_FUNCTIONS_H
#define CT_FBO_FUNCTIONS_H

#define CT_FBO_FUNCTIONS(X)                                                              \
    X(PFNGLGENFRAMEBUFFERSOESPROC, glGenFramebuffersOES)                                 \
    X(PFNGLDELETEFRAMEBUFFERSOESPROC, glDeleteFramebuffersOES)                           \
    X(PFNGLBINDFRAMEBUFFEROESPROC, glBindFramebufferOES)                                 \
    X(PFNGLISFRAMEBUFFEROESPROC, glIsFramebufferOES)                                     \
    X(PFNGLGENRENDERBUFFERSOESPROC, glGenRenderbuffersOES)                               \
    X(PFNGLDELETERENDERBUFFERSOESPROC, glDeleteRenderbuffersOES)                         \
    X(PFNGLBINDRENDERBUFFEROESPROC, glBindRenderbufferOES)                               \
    X(PFNGLISRENDERBUFFEROESPROC, glIsRenderbufferOES)                                   \
    X(PFNGLRENDERBUFFERSTORAGEOESPROC, glRenderbufferStorageOES)                         \
    X(PFNGLGETRENDERBUFFERPARAMETERIVOESPROC, glGetRenderbufferParameterivOES)           \
    X(PFNGLFRAMEBUFFERRENDERBUFFEROESPROC, glFramebufferRenderbufferOES)                 \
    X(PFNGLFRAMEBUFFERTEXTURE2DOESPROC, glFramebufferTexture2DOES)                       \
    X(PFNGLCHECKFRAMEBUFFERSTATUSOESPROC, glCheckFramebufferStatusOES)                   \
    X(PFNGLGETFRAMEBUFFERATTACHMENTPARAMETERIVOESPROC,                                   \
      glGetFramebufferAttachmentParameterivOES)                                          \
    X(PFNGLGENERATEMIPMAPOESPROC, glGenerateMipmapOES)

#define CT_FBO_DECLARE(type, name) static type name;
CT_FBO_FUNCTIONS(CT_FBO_DECLARE)
#undef CT_FBO_DECLARE

/* Looks every function up; true when all were found (a CHECK counts the answer). */
static CT_UNUSED int ct_load_fbo(void)
{
    int all = 1;
#define CT_FBO_LOAD(type, name)                                                          \
    name = (type)eglGetProcAddress(#name);                                               \
    all = all && name != NULL;
    CT_FBO_FUNCTIONS(CT_FBO_LOAD)
#undef CT_FBO_LOAD
    CHECK(all);
    return all;
}

#endif
