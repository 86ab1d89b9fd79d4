#include "skeleton_drawing.h"

#include <GL/glew.h>
#include <GL/glu.h>

#include <QWidget>

#include <algorithm>
#include <cmath>

namespace pcskeleton::edit {

namespace {

// Nodes are yellow and selected ones red: distinct on MeshLab's grey cloud, and what the
// GUI test looks for in screenshots.
const float kNodeColour[3] = {1.0f, 0.85f, 0.0f};
const float kSelectedColour[3] = {1.0f, 0.1f, 0.1f};
const float kBoneColour[3] = {0.15f, 0.35f, 1.0f};
const float kSelectedBoneColour[3] = {1.0f, 0.55f, 0.0f};  // both ends selected
const float kInferredBoneColour[3] = {0.85f, 0.1f, 0.85f};  // dashed: a bone the data does not show
const float kRadiusFieldColour[4] = {0.3f, 0.7f, 1.0f, 0.25f};

// Draws with a GLU quadric, created once per frame.
class Quadric {
public:
    Quadric() : q_(gluNewQuadric()) {}
    ~Quadric() { gluDeleteQuadric(q_); }
    Quadric(const Quadric&) = delete;
    Quadric& operator=(const Quadric&) = delete;

    void sphere(const Point& centre, double radius) const {
        glPushMatrix();
        glTranslated(centre.x(), centre.y(), centre.z());
        gluSphere(q_, radius, 16, 12);
        glPopMatrix();
    }
    // A truncated cone from `a` (radius ra) to `b` (radius rb).
    void cone(const Point& a, double ra, const Point& b, double rb) const {
        const Point axis = b - a;
        const double length = axis.norm();
        if (length <= 0.0) return;
        const Point direction = axis / length;
        const Point turnAxis = Point::UnitZ().cross(direction);
        const double degrees = std::acos(std::clamp(direction.z(), -1.0, 1.0)) * 180.0 / M_PI;
        glPushMatrix();
        glTranslated(a.x(), a.y(), a.z());
        if (turnAxis.norm() > 1e-9) glRotated(degrees, turnAxis.x(), turnAxis.y(), turnAxis.z());
        else if (direction.z() < 0) glRotated(180.0, 1, 0, 0);
        gluCylinder(q_, ra, rb, length, 16, 1);
        glPopMatrix();
    }

private:
    GLUquadric* q_;
};

}  // namespace

void drawBones(const SkeletonGraph& graph, const PointList& nodes, const std::vector<bool>& selected) {
    glDisable(GL_LIGHTING);
    glLineWidth(3.0f);
    const std::vector<char> inferred = inferredFlags(graph);
    for (const bool dashed : {false, true}) {
        if (dashed) {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(2, 0x0F0F);
        }
        glBegin(GL_LINES);
        for (std::size_t i = 0; i < graph.edges.size(); ++i) {
            if (bool(inferred[i]) != dashed) continue;
            const Edge& e = graph.edges[i];
            glColor3fv(selected[e[0]] && selected[e[1]] ? kSelectedBoneColour
                                                        : dashed ? kInferredBoneColour : kBoneColour);
            glVertex3dv(nodes[e[0]].data());
            glVertex3dv(nodes[e[1]].data());
        }
        glEnd();
    }
    glDisable(GL_LINE_STIPPLE);
}

void drawNodes(const PointList& nodes, const std::vector<bool>& selected, double markerSize) {
    glEnable(GL_LIGHTING);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_NORMALIZE);
    const Quadric quadric;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        glColor3fv(selected[n] ? kSelectedColour : kNodeColour);
        quadric.sphere(nodes[n], markerSize * (selected[n] ? 1.3 : 1.0));
    }
}

void drawRadiusField(const SkeletonGraph& graph, const PointList& nodes) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glEnable(GL_LIGHTING);
    glEnable(GL_COLOR_MATERIAL);
    glColor4fv(kRadiusFieldColour);
    const Quadric quadric;
    for (const Edge& e : graph.edges) quadric.cone(nodes[e[0]], graph.radii[e[0]], nodes[e[1]], graph.radii[e[1]]);
    for (std::size_t n = 0; n < nodes.size(); ++n) quadric.sphere(nodes[n], graph.radii[n]);
}

void drawRubberBand(const QWidget& view, const QPoint& from, const QPoint& to) {
    const double ratio = view.devicePixelRatio();
    const auto glY = [&](int y) { return (view.height() - y) * ratio; };
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(0, view.width() * ratio, 0, view.height() * ratio, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glLineWidth(1.5f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_LINE_LOOP);
    glVertex2d(from.x() * ratio, glY(from.y()));
    glVertex2d(to.x() * ratio, glY(from.y()));
    glVertex2d(to.x() * ratio, glY(to.y()));
    glVertex2d(from.x() * ratio, glY(to.y()));
    glEnd();
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopAttrib();
}

}  // namespace pcskeleton::edit
