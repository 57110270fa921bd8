/*
 * Lighting as ES 1.1 §2.12.1 states it, checked in pixels: a full-viewport quad with one
 * normal is lit to one color, which is compared with the hand-computed value of the
 * specification's equation (tolerance 1 step for rounding to 8 bits). Covers the default
 * light and material, the per-light ambient term inside attenuation (the book's Eq. 3.3
 * would give twice the value), spot cutoffs 90 and 180, lights specified under a rotated
 * modelview, a zero attenuation denominator (our documented saturation), two-sided lighting,
 * NORMALIZE (zero-length normals included), RESCALE_NORMAL against NORMALIZE under uniform
 * and non-uniform scale, a singular modelview, COLOR_MATERIAL and smooth vs flat shading.
 */
#include "common.h"

static void view(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(-1, 1, -1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* Draws the quad [-s, s]^2 at z = 0 with normal n, counter-clockwise unless `cw`. */
static void quad(GLfloat s, GLfloat nx, GLfloat ny, GLfloat nz, int cw)
{
    GLfloat ccw_v[8], cw_v[8];
    GLfloat a[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
    GLfloat b[8] = {-1, -1, -1, 1, 1, -1, 1, 1};
    int i;
    for (i = 0; i < 8; ++i) {
        ccw_v[i] = a[i] * s;
        cw_v[i] = b[i] * s;
    }
    glClearColor(0, 0, 1, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glNormal3f(nx, ny, nz);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, cw ? cw_v : ccw_v);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void reset_light(void)
{
    static const GLfloat black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
    static const GLfloat dir[4] = {0, 0, 1, 0}, spot[3] = {0, 0, -1};
    static const GLfloat amb[4] = {0.2f, 0.2f, 0.2f, 1}, dif[4] = {0.8f, 0.8f, 0.8f, 1};
    view();
    glLightfv(GL_LIGHT0, GL_AMBIENT, black);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, spot);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 0);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
    glDisable(GL_NORMALIZE);
    glDisable(GL_RESCALE_NORMAL);
    glDisable(GL_COLOR_MATERIAL);
    glColor4f(1, 1, 1, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
}

/* Every pixel of the quad has gray level g (0..255) and alpha 255. */
#define CHECK_GRAY(g)                                                                    \
    do {                                                                                 \
        CHECK_PIXEL(16, 16, (g), (g), (g), 255, 1);                                      \
        CHECK_PIXEL(1, 30, (g), (g), (g), 255, 1);                                       \
    } while (0)

int main(void)
{
    static const GLfloat zero4[4] = {0, 0, 0, 0};
    ct_init(32, 32);

    /* Defaults: e + a_cm a_cs + d_cm d_cl (n.l) = 0.04 + 0.8 = 0.84 -> 214. */
    reset_light();
    quad(1, 0, 0, 1, 0);
    CHECK_GRAY(214);
    ct_save("defaults");
    /* Facing away: the global ambient only, 0.04 -> 10. */
    quad(1, 0, 0, -1, 0);
    CHECK_GRAY(10);
    /* Lighting off: the current color. */
    glDisable(GL_LIGHTING);
    quad(1, 0, 0, -1, 0);
    CHECK_GRAY(255);
    CHECK_GL(GL_NO_ERROR);

    /* The per-light ambient term is inside att.spot: a light at distance ~1000 with
     * k_l = 0.002 (att = 0.5), ambient 1, nothing else: 0.2 * 1 * 0.5 = 0.1 -> 26 (the
     * book's placement would give 51). */
    {
        static const GLfloat one[4] = {1, 1, 1, 1}, far_pos[4] = {0, 0, 1000, 1};
        reset_light();
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero4);
        glLightfv(GL_LIGHT0, GL_AMBIENT, one);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, zero4);
        glLightfv(GL_LIGHT0, GL_POSITION, far_pos);
        glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0);
        glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.002f);
        quad(1, 0, 0, 1, 0);
        CHECK_GRAY(26);
        ct_save("ambient_inside_attenuation");
    }

    /* Spot lights far above the quad: cutoff 90 lights the half-space in front. */
    {
        static const GLfloat pos[4] = {0, 0, 1000, 1};
        static const GLfloat down[3] = {0, 0, -1}, up[3] = {0, 0, 1};
        reset_light();
        glLightfv(GL_LIGHT0, GL_POSITION, pos);
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 90);
        glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, down);
        quad(1, 0, 0, 1, 0);
        CHECK_GRAY(214);
        glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, up);
        quad(1, 0, 0, 1, 0);
        CHECK_GRAY(10);
        /* Cutoff 180: no cone, whatever the direction. */
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
        quad(1, 0, 0, 1, 0);
        CHECK_GRAY(214);
        /* A narrow cone (10 degrees) pointing down with exponent 128: the vertices are
         * ~0.08 degrees off axis, cos^128 = 0.99985, so diffuse stays 0.8. */
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 10);
        glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 128);
        glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, down);
        quad(1, 0, 0, 1, 0);
        CHECK_GRAY(214);
    }

    /* A light specified under a rotated modelview is stored in eye space: (0, 0, -1, 0)
     * under a 180 degree turn about y shines from +z. */
    {
        static const GLfloat back_dir[4] = {0, 0, -1, 0};
        GLfloat p[4];
        reset_light();
        glRotatef(180, 0, 1, 0);
        glLightfv(GL_LIGHT0, GL_POSITION, back_dir);
        glLoadIdentity();
        glGetLightfv(GL_LIGHT0, GL_POSITION, p);
        CHECK(p[2] > 0.999f && p[3] == 0);
        quad(1, 0, 0, 1, 0);
        CHECK_GRAY(214);
        /* The same light set under the identity shines from behind. */
        glLightfv(GL_LIGHT0, GL_POSITION, back_dir);
        quad(1, 0, 0, 1, 0);
        CHECK_GRAY(10);
    }

    /* Zero attenuation denominator (all coefficients 0): our library saturates every
     * channel the light reaches (documented); Mesa's 1/0 is undefined here. */
    {
        static const GLfloat red[4] = {1, 0, 0, 1}, pos[4] = {0, 0, 1, 1};
        reset_light();
        glLightfv(GL_LIGHT0, GL_DIFFUSE, red);
        glLightfv(GL_LIGHT0, GL_POSITION, pos);
        glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0);
        CHECK_GL(GL_NO_ERROR);
        quad(1, 0, 0, 1, 0);
        if (ct_strict())
            CHECK_PIXEL(16, 16, 255, 10, 10, 255, 1);
    }

    /* Two-sided lighting: a clockwise (back-facing) quad whose normal faces the light is lit
     * with the reversed normal: ambient only. Without it, the front color. */
    reset_light();
    quad(1, 0, 0, 1, 1);
    CHECK_GRAY(214);
    glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1);
    quad(1, 0, 0, 1, 1);
    CHECK_GRAY(10);
    quad(1, 0, 0, -1, 1);
    CHECK_GRAY(214);
    quad(1, 0, 0, 1, 0);
    CHECK_GRAY(214);
    ct_save("two_side");

    /* NORMALIZE: a normal of length 5 saturates without it; a zero normal lights only the
     * ambient terms. */
    reset_light();
    quad(1, 0, 0, 5, 0);
    CHECK_GRAY(255);
    glEnable(GL_NORMALIZE);
    quad(1, 0, 0, 5, 0);
    CHECK_GRAY(214);
    quad(1, 0, 0, 0, 0);
    CHECK_GRAY(10);

    /* Uniform scale 0.5: normals come out twice as long; RESCALE_NORMAL and NORMALIZE both
     * restore them. */
    reset_light();
    glScalef(0.5f, 0.5f, 0.5f);
    quad(2, 0, 0, 1, 0);
    CHECK_GRAY(255);
    glEnable(GL_RESCALE_NORMAL);
    quad(2, 0, 0, 1, 0);
    CHECK_GRAY(214);
    /* Non-uniform scale (0.5, 0.5, 1) and normal (0.6, 0, 0.8): the eye normal is
     * (1.2, 0, 0.8). RESCALE_NORMAL (factor 1 from the z row) keeps it: 0.04 + 0.8 * 0.8
     * = 0.68 -> 173; NORMALIZE makes n.l = 0.5547: 0.4838 -> 123. */
    glLoadIdentity();
    glScalef(0.5f, 0.5f, 1);
    quad(2, 0.6f, 0, 0.8f, 0);
    CHECK_GRAY(173);
    glDisable(GL_RESCALE_NORMAL);
    glEnable(GL_NORMALIZE);
    quad(2, 0.6f, 0, 0.8f, 0);
    CHECK_GRAY(123);
    ct_save("rescale_normalize");

    /* A singular modelview (scale z by 0): positions flatten, normals pass through
     * untransformed (no inverse exists), lighting on or off gives defined colors. */
    reset_light();
    glScalef(1, 1, 0);
    quad(1, 0, 0, 1, 0);
    CHECK_GRAY(214);
    glDisable(GL_LIGHTING);
    quad(1, 0, 0, 1, 0);
    CHECK_GRAY(255);

    /* COLOR_MATERIAL: the current color becomes ambient and diffuse:
     * 0.5 * 0.2 + 0.5 * 0.8... here light diffuse 1: 0.5 * 0.2 + 0.5 * 1 = 0.6 -> 153;
     * alpha = the color's 0.5 -> 128. */
    reset_light();
    glEnable(GL_COLOR_MATERIAL);
    glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
    quad(1, 0, 0, 1, 0);
    CHECK_PIXEL(16, 16, 153, 153, 153, 128, 1);
    {
        GLfloat m[4];
        glGetMaterialfv(GL_FRONT, GL_DIFFUSE, m);
        CHECK(m[0] == 0.5f && m[3] == 0.5f);
    }
    glDisable(GL_COLOR_MATERIAL);

    /* Per-vertex normals, smooth vs flat: a strip whose last vertex faces the light. */
    {
        static const GLfloat v[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
        static const GLfloat n[12] = {0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, 1};
        reset_light();
        glClear(GL_COLOR_BUFFER_BIT);
        glEnableClientState(GL_NORMAL_ARRAY);
        glNormalPointer(GL_FLOAT, 0, n);
        glVertexPointer(2, GL_FLOAT, 0, v);
        glShadeModel(GL_FLAT);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        /* Triangle (1, 2, 3) (upper right) takes vertex 3's color; (0, 1, 2) vertex 2's. */
        CHECK_PIXEL(28, 28, 214, 214, 214, 255, 1);
        CHECK_PIXEL(3, 3, 10, 10, 10, 255, 1);
        glShadeModel(GL_SMOOTH);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        CHECK_PIXEL(3, 3, 10, 10, 10, 255, 1);
        glDisableClientState(GL_NORMAL_ARRAY);
        ct_save("flat_smooth");
    }

    /* §2.12.7 clamps the lit color to [0, 1] before texturing: a light of diffuse 2 gives
     * 0.04 + 1.6 -> 1, and MODULATE with a gray 128 texel gives 128, not 0.82 * 255. */
    {
        static const GLfloat two[4] = {2, 2, 2, 1};
        static const GLubyte gray[4] = {128, 128, 128, 255};
        GLuint tex;
        GLubyte px[4];
        reset_light();
        glLightfv(GL_LIGHT0, GL_DIFFUSE, two);
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, gray);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        glEnable(GL_TEXTURE_2D);
        quad(1, 0, 0, 1, 0);
        glReadPixels(16, 16, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        /* No image: the differential run would flag the known deviation. */
        CHECK_MESA_DEVIATES(px[0] >= 127 && px[0] <= 129,
                            "Mesa modulates the unclamped lit color");
        glDisable(GL_TEXTURE_2D);
        glDeleteTextures(1, &tex);
    }
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
