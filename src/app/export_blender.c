/*
 * app/export_blender.c -- the scene as a Python script that builds it in Blender 3.4+ and
 * renders it with Cycles:
 *
 *     blender -b --factory-startup -P SCENE.py -- IMAGE.exr     (or IMAGE.pfm)
 *
 * The script starts from an empty scene, so nothing of Blender's defaults (the cube, the
 * lamp, 0.1 m clipping) leaks in. It is two parts: fixed helpers (PREAMBLE below) and the
 * scene as calls to them with our numbers, every one printed with %.9g (Blender stores
 * floats, which 9 digits give back exactly). Conventions, each one a way to get a
 * different picture:
 *   - Camera. A camera of sensor_fit VERTICAL and angle_y our full vertical field of
 *     view in radians. Blender's camera looks down its local -z with +y up and +x right,
 *     so its world matrix has the columns u, v, -w and from: our right-handed frame
 *     (camera.h) as it is, not mirrored. Clipping from 1e-6 to 10 times the scene's reach.
 *     A thin lens is Blender's depth of field: focus_distance ours, a round aperture, and
 *     the f-stop that gives our radius, lens / 1000 / (2 radius), lens the focal length in
 *     millimetres Blender derives from angle_y (Cycles' lens radius is lens / 1000 over
 *     twice the f-stop, in scene units).
 *   - Pixels. A box filter of width 1 pixel: the pixel is the mean over its square.
 *     Film exposure 1, view transform Standard; the EXR holds linear RGB as rendered.
 *   - Sampling. Cycles' CPU path tracer, es->spp samples, no denoising, no adaptive
 *     sampling, no clamping, filter glossy 0, caustics on, every bounce limit 1024 (paths
 *     end by Cycles' Russian roulette), light threshold 0, no light tree: nothing biased.
 *   - Area lights. Cycles' emission shader of strength 1 and colour Le is radiance Le on
 *     both sides of a mesh; a Mix on Geometry.Backfacing leaves the back side dark, so
 *     emitters are one-sided unless two_sided, as ours. The material still reflects.
 *   - Point lights. A Cycles point light of radius 0 and power P has intensity P / (4 pi)
 *     (the kernel's eval_fac = 1 / (4 pi) with "intensity instead of radiance" at radius
 *     0; measured on scenes/analytic/point-over-plane.scene: mean ratio 0.9999): so P is
 *     our Phi, written as energy max(Phi) and colour Phi / max(Phi).
 *   - Background. The World's Background shader of colour b, strength 1: radiance b.
 *   - Materials. Lambert is a Diffuse BSDF of roughness 0; a mirror a sharp Glossy BSDF
 *     of colour rho (no Fresnel, as ours); glass a Mix, by a Fresnel node of our ior, of a
 *     sharp Refraction BSDF of colour 1 - absorption and a white sharp Glossy: exact
 *     dielectric Fresnel (Cycles inverts the ior on back faces, and the Fresnel is 1 at
 *     total internal reflection) with our filter on refraction only. Cycles does not scale
 *     radiance by 1/eta^2 on refraction; for light that enters and leaves a body the
 *     factors cancel, so only an emitter or the camera inside glass would differ. Phong,
 *     Ward and Schlick have no equivalent: a Diffuse plus a Glossy lobe (Beckmann of
 *     alpha sqrt(2/(n+2)) for Phong, sqrt(ax ay) for Ward; for Schlick our own split
 *     a, b, c into Diffuse, GGX of alpha sqrt(r) and a sharp mirror), each announced by
 *     export_note.
 *   - Spheres. Cycles' point cloud gives exact spheres: one vertex a sphere with its
 *     radius as an attribute, turned into points by a Geometry Nodes modifier. Cycles
 *     culls a point's back face, so a ray from inside misses it: glass spheres, emitting
 *     ones and those seen from inside (holding the camera, a point light or an emitting
 *     sphere's centre) become icospheres (subdivision SPHERE_LEVEL, smooth shading)
 *     scaled to the sphere's area 4 pi r^2, so an emitter keeps its power; export_note
 *     says so.
 *   - Units. Our lengths times UNIT = 2^-k are Blender's, k the smallest that brings the
 *     scene within one unit of the camera (a power of 2: the scaling is exact). Cycles 3.4
 *     samples a triangle light by its solid angle, computed with an approximate arccos,
 *     unless the longest edge times twice the area is below the distance to its plane, a
 *     test in absolute units: at our millimetres the Cornell box came out 1-1.4% dark
 *     where the light is seen at grazing angles, a light cut into small triangles tens of %;
 *     within a unit every triangle is sampled by area, exactly. Radiance does not change
 *     with scale; a point light's power is multiplied by UNIT^2.
 *   - Meshes. Flat lists of numbers in a string that floats() splits (a Python literal
 *     of a million numbers costs its compiler gigabytes), one triangle a line, vertices not
 *     shared; vertex normals become custom split normals (Blender keeps them to about
 *     1e-4 rad), with Cycles' shadow-terminator offsets set to 0.
 *   - Output. A name ending in ".pfm" makes the script render to a temporary EXR and
 *     write a PFM ("PF", width height, -1.0, little-endian floats, bottom row first).
 */
#include <math.h>
#include <string.h>

#include "../base/alloc.h"
#include "export.h"

#define PI 3.14159265358979323846

/* Icosphere subdivisions for a sphere that must be a mesh: 81,920 triangles, whose
 * flat facets depart from the sphere by at most about 4e-5 of its radius. */
#define SPHERE_LEVEL 6

/* The helpers, one Python line a string (C99 promises string literals of 4095 bytes only). */
static const char *const PREAMBLE[] = {
    "import bpy, math, os, struct, sys, tempfile",
    "from mathutils import Matrix",
    "",
    "bpy.ops.wm.read_factory_settings(use_empty=True)",
    "scene = bpy.context.scene",
    "argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []",
    "OUT = os.path.abspath(argv[0] if argv else 'render.exr')",
    "",
    "def setting(owner, name, value):",
    "    # an option another Blender lacks is skipped: one script for 3.4 to 4.x",
    "    if hasattr(owner, name):",
    "        setattr(owner, name, value)",
    "",
    "def settings(width, height, spp):",
    "    r = scene.render",
    "    r.engine = 'CYCLES'",
    "    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100",
    "    r.pixel_aspect_x = r.pixel_aspect_y = 1.0",
    "    r.film_transparent = r.use_compositing = r.use_sequencer = False",
    "    r.dither_intensity = 0.0",
    "    r.use_file_extension = False",
    "    im = r.image_settings",
    "    im.file_format, im.color_depth, im.color_mode = 'OPEN_EXR', '32', 'RGB'",
    "    im.exr_codec = 'ZIP'",
    "    v = scene.view_settings",
    "    v.view_transform, v.look, v.exposure, v.gamma = 'Standard', 'None', 0.0, 1.0",
    "    c = scene.cycles",
    "    c.device, c.samples = 'CPU', spp",
    "    # bounce limits out of reach: Cycles' own Russian roulette ends the paths",
    "    for name in ('max_bounces', 'diffuse_bounces', 'glossy_bounces',",
    "                 'transmission_bounces', 'volume_bounces', 'transparent_max_bounces'):",
    "        setattr(c, name, 1024)",
    "    # nothing that trades bias for noise",
    "    c.min_light_bounces = c.min_transparent_bounces = 0",
    "    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0",
    "    c.blur_glossy = 0.0",
    "    c.caustics_reflective = c.caustics_refractive = True",
    "    c.use_denoising = c.use_adaptive_sampling = False",
    "    c.light_sampling_threshold = 0.0",
    "    for name in ('use_light_tree', 'use_fast_gi', 'auto_scrambling_distance',",
    "                 'use_preview_denoising'):",
    "        setting(c, name, False)",
    "    setting(c, 'scrambling_distance', 1.0)",
    "    # a pixel is the mean over its square: a box 1 pixel wide; exposure 1",
    "    c.pixel_filter_type, c.filter_width, c.film_exposure = 'BOX', 1.0, 1.0",
    "    c.seed = 0",
    "",
    "def floats(text):",
    "    # numbers as one string, parsed at run time: a literal of a million numbers",
    "    # would cost Python's compiler gigabytes",
    "    return [float(x) for x in text.split()]",
    "",
    "def scaled(V):",
    "    # our lengths in Blender's units: times UNIT, a power of 2, so exactly",
    "    return [UNIT * x for x in V]",
    "",
    "def camera(rows, angle_y, clip_start, clip_end, lens_radius, focus):",
    "    rows = [r[:3] + (UNIT * r[3],) for r in rows[:3]] + [rows[3]]",
    "    data = bpy.data.cameras.new('camera')",
    "    data.type, data.sensor_fit = 'PERSP', 'VERTICAL'",
    "    data.angle_y = angle_y",
    "    data.shift_x = data.shift_y = 0.0",
    "    data.clip_start, data.clip_end = UNIT * clip_start, UNIT * clip_end",
    "    if lens_radius > 0:",
    "        # Cycles' lens radius is lens / 1000 / (2 f-stop), lens the focal length in mm",
    "        # that angle_y gave; a round aperture (no blades), focused on the plane at",
    "        # focus_distance along the view direction",
    "        data.dof.use_dof = True",
    "        data.dof.focus_distance = UNIT * focus",
    "        data.dof.aperture_blades = 0",
    "        data.dof.aperture_ratio = 1.0",
    "        data.dof.aperture_fstop = data.lens / 1000.0 / (2.0 * UNIT * lens_radius)",
    "    ob = bpy.data.objects.new('camera', data)",
    "    ob.matrix_world = Matrix(rows)",
    "    scene.collection.objects.link(ob)",
    "    scene.camera = ob",
    "",
    "def world(radiance):",
    "    w = bpy.data.worlds.new('background')",
    "    w.use_nodes = True",
    "    bg = w.node_tree.nodes['Background']",
    "    bg.inputs['Color'].default_value = radiance + (1.0,)",
    "    bg.inputs['Strength'].default_value = 1.0",
    "    scene.world = w",
    "",
    "def sharp(node):",
    "    # a perfectly smooth lobe: 'SHARP' before Blender 4.0, GGX of roughness 0 after",
    "    if 'SHARP' in node.bl_rna.properties['distribution'].enum_items.keys():",
    "        node.distribution = 'SHARP'",
    "    else:",
    "        node.distribution = 'GGX'",
    "        node.inputs['Roughness'].default_value = 0.0",
    "    return node",
    "",
    "def shader(nt, kind, colour=None, **inputs):",
    "    n = nt.nodes.new(kind)",
    "    if colour is not None:",
    "        n.inputs['Color'].default_value = colour + (1.0,)",
    "    for name, value in inputs.items():",
    "        n.inputs[name].default_value = value",
    "    return n",
    "",
    "def mix(nt, fac, a, b):",
    "    # a where fac is 0, b where it is 1; an input left unlinked is no light at all",
    "    m = nt.nodes.new('ShaderNodeMixShader')",
    "    nt.links.new(fac, m.inputs[0])",
    "    for shader_in, node in ((m.inputs[1], a), (m.inputs[2], b)):",
    "        if node is not None:",
    "            nt.links.new(node.outputs[0], shader_in)",
    "    return m",
    "",
    "def add(nt, a, b):",
    "    s = nt.nodes.new('ShaderNodeAddShader')",
    "    nt.links.new(a.outputs[0], s.inputs[0])",
    "    nt.links.new(b.outputs[0], s.inputs[1])",
    "    return s",
    "",
    "BLACK, WHITE = (0.0, 0.0, 0.0), (1.0, 1.0, 1.0)",
    "",
    "def material(name, kind, rho=BLACK, rho_s=BLACK, mirror=BLACK, ior=1.0, filter=WHITE,",
    "             distribution='GGX', roughness=0.0, emission=BLACK, two_sided=False):",
    "    m = bpy.data.materials.new(name)",
    "    m.use_nodes = True",
    "    nt = m.node_tree",
    "    nt.nodes.clear()",
    "    if kind == 'lambert':",
    "        s = shader(nt, 'ShaderNodeBsdfDiffuse', rho, Roughness=0.0)",
    "    elif kind == 'mirror':",
    "        s = sharp(shader(nt, 'ShaderNodeBsdfGlossy', rho))",
    "    elif kind == 'glass':",
    "        # exact Fresnel of our ior (inverted on back faces, 1 at total internal",
    "        # reflection) choosing between refraction through the filter and a mirror",
    "        fresnel = shader(nt, 'ShaderNodeFresnel', IOR=ior)",
    "        refract = sharp(shader(nt, 'ShaderNodeBsdfRefraction', filter, IOR=ior))",
    "        reflect = sharp(shader(nt, 'ShaderNodeBsdfGlossy', WHITE))",
    "        s = mix(nt, fresnel.outputs[0], refract, reflect)",
    "    else:",
    "        # Phong, Ward, Schlick: diffuse, a microfacet lobe, a mirror (approximations)",
    "        g = shader(nt, 'ShaderNodeBsdfGlossy', rho_s, Roughness=roughness)",
    "        g.distribution = distribution",
    "        s = add(nt, shader(nt, 'ShaderNodeBsdfDiffuse', rho, Roughness=0.0), g)",
    "        if max(mirror) > 0.0:",
    "            s = add(nt, s, sharp(shader(nt, 'ShaderNodeBsdfGlossy', mirror)))",
    "    if max(emission) > 0.0:",
    "        e = shader(nt, 'ShaderNodeEmission', emission, Strength=1.0)",
    "        if not two_sided:",
    "            # the back side emits nothing: Backfacing is 1 there",
    "            back = nt.nodes.new('ShaderNodeNewGeometry').outputs['Backfacing']",
    "            e = mix(nt, back, e, None)",
    "        s = add(nt, s, e)",
    "    out = nt.nodes.new('ShaderNodeOutputMaterial')",
    "    nt.links.new(s.outputs[0], out.inputs['Surface'])",
    "    return m",
    "",
    "def point_light(position, energy, colour):",
    "    data = bpy.data.lights.new('point light', 'POINT')",
    "    # intensity falls as 1 / distance^2: in Blender's units the power is UNIT^2 ours",
    "    data.energy, data.color = UNIT * UNIT * energy, colour",
    "    data.shadow_soft_size = 0.0",
    "    setting(data.cycles, 'max_bounces', 1024)",
    "    ob = bpy.data.objects.new('point light', data)",
    "    ob.location = scaled(position)",
    "    scene.collection.objects.link(ob)",
    "",
    "def link(name, me, mat):",
    "    me.materials.append(mat)",
    "    ob = bpy.data.objects.new(name, me)",
    "    scene.collection.objects.link(ob)",
    "    # no shadow-terminator offsets: they move shadow rays off the surface (a bias)",
    "    setting(ob.cycles, 'shadow_terminator_geometry_offset', 0.0)",
    "    setting(ob.cycles, 'shadow_terminator_offset', 0.0)",
    "    return ob",
    "",
    "def mesh(name, mat, V, N=None):",
    "    n = len(V) // 3",
    "    me = bpy.data.meshes.new(name)",
    "    me.vertices.add(n)",
    "    me.vertices.foreach_set('co', scaled(V))",
    "    me.loops.add(n)",
    "    me.loops.foreach_set('vertex_index', range(n))",
    "    me.polygons.add(n // 3)",
    "    me.polygons.foreach_set('loop_start', range(0, n, 3))",
    "    if not bpy.types.MeshPolygon.bl_rna.properties['loop_total'].is_readonly:",
    "        me.polygons.foreach_set('loop_total', (3,) * (n // 3))",
    "    me.update()",
    "    if N is not None:",
    "        # our vertex normals as custom split normals (a vertex has one loop)",
    "        me.polygons.foreach_set('use_smooth', (True,) * (n // 3))",
    "        setting(me, 'use_auto_smooth', True)",
    "        me.normals_split_custom_set_from_vertices(",
    "            [N[i:i + 3] for i in range(0, len(N), 3)])",
    "    link(name, me, mat)",
    "",
    "def spheres(name, mat, C, R):",
    "    # exact spheres: Cycles' point cloud, from one vertex a sphere by Geometry Nodes",
    "    me = bpy.data.meshes.new(name)",
    "    me.vertices.add(len(R))",
    "    me.vertices.foreach_set('co', scaled(C))",
    "    me.attributes.new('radius', 'FLOAT', 'POINT').data.foreach_set('value', scaled(R))",
    "    ob = link(name, me, mat)",
    "    ng = bpy.data.node_groups.new(name, 'GeometryNodeTree')",
    "    if hasattr(ng, 'interface'):",
    "        for io in ('INPUT', 'OUTPUT'):",
    "            ng.interface.new_socket('Geometry', in_out=io,",
    "                                    socket_type='NodeSocketGeometry')",
    "    else:",
    "        ng.inputs.new('NodeSocketGeometry', 'Geometry')",
    "        ng.outputs.new('NodeSocketGeometry', 'Geometry')",
    "    nodes = ng.nodes",
    "    attr = nodes.new('GeometryNodeInputNamedAttribute')",
    "    attr.data_type = 'FLOAT'",
    "    attr.inputs['Name'].default_value = 'radius'",
    "    points = nodes.new('GeometryNodeMeshToPoints')",
    "    setm = nodes.new('GeometryNodeSetMaterial')",
    "    setm.inputs['Material'].default_value = mat",
    "    ng.links.new(nodes.new('NodeGroupInput').outputs[0], points.inputs['Mesh'])",
    "    ng.links.new([s for s in attr.outputs if s.enabled][0], points.inputs['Radius'])",
    "    ng.links.new(points.outputs[0], setm.inputs['Geometry'])",
    "    ng.links.new(setm.outputs[0], nodes.new('NodeGroupOutput').inputs[0])",
    "    ob.modifiers.new('spheres', 'NODES').node_group = ng",
    "",
    "def sphere_mesh(name, mat, centre, radius, level):",
    "    # a sphere as an icosphere, smooth shaded, scaled to the sphere's area 4 pi r^2",
    "    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=level, radius=1.0)",
    "    ob = bpy.context.active_object",
    "    me = ob.data",
    "    me.polygons.foreach_set('use_smooth', (True,) * len(me.polygons))",
    "    s = UNIT * radius * math.sqrt(4.0 * math.pi / sum(p.area for p in me.polygons))",
    "    ob.scale, ob.location, ob.name = (s, s, s), scaled(centre), name",
    "    me.materials.append(mat)",
    "",
    "def render():",
    "    pfm = OUT.lower().endswith('.pfm')",
    "    exr = OUT",
    "    if pfm:",
    "        fd, exr = tempfile.mkstemp(suffix='.exr')",
    "        os.close(fd)",
    "    scene.render.filepath = exr",
    "    bpy.ops.render.render(write_still=True)",
    "    if pfm:",
    "        # Blender's pixels run from the bottom row up, as a PFM's do",
    "        img = bpy.data.images.load(exr)",
    "        (w, h), k = img.size, img.channels",
    "        px = img.pixels[:]",
    "        rgb = [px[i + c] for i in range(0, w * h * k, k) for c in range(3)]",
    "        with open(OUT, 'wb') as f:",
    "            f.write(b'PF\\n%d %d\\n-1.0\\n' % (w, h))",
    "            f.write(struct.pack('<%df' % len(rgb), *rgb))",
    "        bpy.data.images.remove(img)",
    "        os.remove(exr)",
};

/* ---- small writers ---- */

/* A Python string literal of any bytes: printable ASCII as it is, the rest escaped, so
 * that no material name can break the script or make it other than ASCII. */
static void py_string(FILE *f, const char *s)
{
    fputc('\'', f);
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '\'' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c >= 32 && c < 127)
            fputc(c, f);
        else
            fprintf(f, "\\x%02x", c);
    }
    fputc('\'', f);
}

static void py_vec(FILE *f, struct vec3 v)
{
    fputc('(', f);
    export_rgb(f, ", ", v);
    fputc(')', f);
}

/* A flat list of points as floats('''...'''), `per` points (a triangle: 3) a line. */
static void py_points(FILE *f, const struct vec3 *p, size_t n, size_t per)
{
    fputs("floats('''", f);
    for (size_t i = 0; i < n; i++)
        fprintf(f, "%s%.9g %.9g %.9g", i % per == 0 ? "\n" : "  ", p[i].x, p[i].y, p[i].z);
    fputs("''')", f);
}

/* ---- the scene ---- */

/* How far the scene reaches from the camera: the clipping range must hold it all. */
static double reach(const struct export_scene *es)
{
    struct vec3 from = es->camera.from;
    double r = 1.0;
    for (size_t i = 0; i < es->n_spheres; i++) {
        double d = vec3_length(vec3_sub(es->spheres[i].centre, from)) + es->spheres[i].radius;
        r = d > r ? d : r;
    }
    for (size_t i = 0; i < es->n_meshes; i++)
        for (size_t k = 0; k < 3 * es->meshes[i].n_triangles; k++) {
            double d = vec3_length(vec3_sub(es->meshes[i].vertices[k], from));
            r = d > r ? d : r;
        }
    for (size_t i = 0; i < es->n_point_lights; i++) {
        double d = vec3_length(vec3_sub(es->point_lights[i].position, from));
        r = d > r ? d : r;
    }
    return r;
}

static void write_camera(FILE *f, const struct export_scene *es)
{
    const struct camera *c = &es->camera;
    /* + 0.0 turns a -0 into 0, only for the reader's eye */
    struct vec3 u = vec3_add(c->u, vec3_zero()), v = vec3_add(c->v, vec3_zero());
    struct vec3 w = vec3_sub(vec3_zero(), c->w), p = c->from;
    double r = reach(es);
    fprintf(f, "# camera: our vertical field of view %.9g degrees; world matrix of columns\n"
               "# u (right), v (up), -w (Blender looks down -z) and the position\n", c->fov);
    fprintf(f, "camera(((%.9g, %.9g, %.9g, %.9g),\n", u.x, v.x, w.x, p.x);
    fprintf(f, "        (%.9g, %.9g, %.9g, %.9g),\n", u.y, v.y, w.y, p.y);
    fprintf(f, "        (%.9g, %.9g, %.9g, %.9g),\n", u.z, v.z, w.z, p.z);
    fprintf(f, "        (0, 0, 0, 1)), %.9g, %.9g, %.9g, %.9g, %.9g)\n", c->fov * PI / 180.0,
            1e-6 * r, 10.0 * r, c->lens_radius, c->lens_radius > 0 ? c->focus : 0.0);
}

static const char *model_name(enum material_kind kind)
{
    return kind == MATERIAL_PHONG ? "Phong" : kind == MATERIAL_WARD ? "Ward" : "Schlick";
}

/* Phong, Ward and Schlick: the closest Cycles has, and a note of what differs. Blender's
 * roughness is sqrt(alpha) (Cycles squares it). */
static void write_glossy(FILE *f, const struct material *m)
{
    struct vec3 diffuse = m->rho, glossy = m->rho_s, mirror = vec3_zero();
    const char *distribution = "BECKMANN";
    double alpha;
    if (m->kind == MATERIAL_PHONG) {
        /* the Beckmann lobe whose slopes match a cosine lobe of exponent n */
        alpha = sqrt(2.0 / (m->exponent + 2.0));
    } else if (m->kind == MATERIAL_WARD) {
        /* Ward's lobe is Beckmann's slope distribution; Cycles' Glossy is isotropic */
        alpha = sqrt(m->alpha_x * m->alpha_y);
    } else {
        /* scene/schlick.c: C [a Lambert + b GGX(alpha^2 = r)] + C c mirror */
        double r = m->roughness, b = 4.0 * r * (1.0 - r);
        double a = r >= 0.5 ? 1.0 - b : 0.0, c = r >= 0.5 ? 0.0 : 1.0 - b;
        diffuse = vec3_scale(m->rho, a);
        glossy = vec3_scale(m->rho, b);
        mirror = vec3_scale(m->rho, c);
        alpha = sqrt(r);
        distribution = "GGX";
    }
    fprintf(f, "'glossy', rho=");
    py_vec(f, diffuse);
    fprintf(f, ", rho_s=");
    py_vec(f, glossy);
    fprintf(f, ", mirror=");
    py_vec(f, mirror);
    fprintf(f, ",\n    distribution='%s', roughness=%.9g", distribution, sqrt(alpha));
    if (m->kind == MATERIAL_SCHLICK)
        export_note("blender: material \"%s\": Schlick's model as Diffuse + GGX (alpha %.3g) "
                    "+ a sharp mirror in our proportions; %s", m->name, alpha,
                    m->isotropy < 1 ? "its anisotropy is dropped (isotropic lobe)"
                                    : "Cycles' GGX masking may differ slightly");
    else
        export_note("blender: material \"%s\": Cycles has no %s model; written as Diffuse + "
                    "Beckmann Glossy (alpha %.3g%s): the highlight's shape and strength "
                    "differ", m->name, model_name(m->kind), alpha,
                    m->kind == MATERIAL_WARD && m->alpha_x != m->alpha_y
                        ? ", isotropic: the anisotropy is dropped" : "");
}

static void write_material(FILE *f, const struct export_scene *es, size_t i)
{
    const struct material *m = &es->materials[i];
    char name[MATERIAL_NAME_MAX + 32];
    snprintf(name, sizeof name, "m%zu %s", i, m->name);
    fprintf(f, "M%zu = material(", i);
    py_string(f, name);
    fprintf(f, ", ");
    switch (m->kind) {
    case MATERIAL_LAMBERT:
    case MATERIAL_MIRROR:
        fprintf(f, "'%s', rho=", m->kind == MATERIAL_LAMBERT ? "lambert" : "mirror");
        py_vec(f, m->rho);
        break;
    case MATERIAL_GLASS:
        fprintf(f, "'glass', ior=%.9g, filter=", m->ior);
        py_vec(f, vec3_sub(vec3(1, 1, 1), m->absorption));
        break;
    default:
        write_glossy(f, m);
    }
    if (material_emits(m)) {
        fprintf(f, ",\n    emission=");
        py_vec(f, m->emission);
        fprintf(f, ", two_sided=%s", m->two_sided ? "True" : "False");
    }
    fprintf(f, ")\n");
}

static void write_lights(FILE *f, const struct export_scene *es)
{
    struct vec3 b = es->background;
    fprintf(f, "# the background: radiance of every ray that leaves the scene\nworld(");
    py_vec(f, b);
    fprintf(f, ")\n");
    for (size_t i = 0; i < es->n_point_lights; i++) {
        const struct light *l = &es->point_lights[i];
        double phi = vec3_max_component(l->power);
        if (phi <= 0)
            continue;
        fprintf(f, "# point light of power %.9g %.9g %.9g W: Cycles' power P gives "
                   "intensity P / (4 pi)\npoint_light(", l->power.x, l->power.y, l->power.z);
        py_vec(f, l->position);
        fprintf(f, ", %.9g, ", phi);
        py_vec(f, vec3_scale(l->power, 1.0 / phi));
        fprintf(f, ")\n");
    }
}

static int inside(struct vec3 p, const struct export_sphere *s)
{
    return vec3_length(vec3_sub(p, s->centre)) < s->radius;
}

/* The emitting spheres, listed once: every sphere is tested against each. */
struct emitters {
    size_t *index;
    size_t n;
};

/* Why sphere i cannot be one of Cycles' points, or NULL when it can. Cycles culls a
 * point's back face (kernel/geom/point_intersect.h), so a ray from inside passes out
 * through it: glass, and a sphere holding the camera, a point light or an emitting
 * sphere's centre, must be a mesh. So must an emitter: Cycles samples only triangles as
 * lights, and the one-sided emission needs the back faces a mesh has. */
static const char *not_points(const struct export_scene *es, const struct emitters *lit,
                              size_t i)
{
    const struct export_sphere *s = &es->spheres[i];
    const struct material *m = &es->materials[s->material];
    if (material_emits(m))
        return "emitting";
    if (m->kind == MATERIAL_GLASS)
        return "glass, which rays cross (Cycles' points have no inside)";
    int seen = inside(es->camera.from, s);
    for (size_t k = 0; k < es->n_point_lights; k++)
        seen |= inside(es->point_lights[k].position, s);
    for (size_t k = 0; k < lit->n; k++)
        seen |= lit->index[k] != i && inside(es->spheres[lit->index[k]].centre, s);
    return seen ? "seen from inside (Cycles' points have no inside)" : NULL;
}

/* The spheres of material k: those Cycles can make exact as one point cloud, the rest as
 * icospheres. */
static void write_spheres(FILE *f, const struct export_scene *es, const struct emitters *lit,
                          int k)
{
    size_t n = 0, written = 0;
    for (size_t i = 0; i < es->n_spheres; i++) {
        const char *why = es->spheres[i].material == k ? not_points(es, lit, i) : NULL;
        if (es->spheres[i].material == k && why == NULL)
            n++;
        else if (why != NULL) {
            export_note("blender: sphere %zu (material \"%s\"): %s; written as an icosphere "
                        "of %d triangles with the sphere's area", i, es->materials[k].name,
                        why, 20 << (2 * SPHERE_LEVEL));
            fprintf(f, "sphere_mesh('sphere %zu', M%d, ", i, k);
            py_vec(f, es->spheres[i].centre);
            fprintf(f, ", %.9g, %d)\n", es->spheres[i].radius, SPHERE_LEVEL);
        }
    }
    if (n == 0)
        return;
    fprintf(f, "spheres('spheres m%d', M%d, floats('''", k, k);
    for (size_t i = 0; i < es->n_spheres; i++)
        if (es->spheres[i].material == k && not_points(es, lit, i) == NULL) {
            struct vec3 c = es->spheres[i].centre;
            fprintf(f, "%s%.9g %.9g %.9g", written++ % 4 == 0 ? "\n" : "  ", c.x, c.y, c.z);
        }
    fprintf(f, "'''),\n    floats('''");
    written = 0;
    for (size_t i = 0; i < es->n_spheres; i++)
        if (es->spheres[i].material == k && not_points(es, lit, i) == NULL)
            fprintf(f, "%s%.9g", written++ % 8 == 0 ? "\n" : " ", es->spheres[i].radius);
    fprintf(f, "'''))\n");
}

static void write_mesh(FILE *f, size_t i, const struct export_mesh *m)
{
    fprintf(f, "mesh('mesh %zu', M%d, ", i, m->material);
    py_points(f, m->vertices, 3 * m->n_triangles, 3);
    if (m->normals != NULL) {
        fprintf(f, ",\n ");
        py_points(f, m->normals, 3 * m->n_triangles, 3);
    }
    fprintf(f, ")\n");
}

int export_blender(FILE *f, const struct export_scene *es, struct error *err)
{
    (void)err; /* nothing to refuse here; a failed write is output_commit()'s to report */
    fprintf(f, "# ");
    export_name(f, es->scene_path != NULL ? es->scene_path : "scene");
    fprintf(f, " for Blender 3.4+ (Cycles), written by photon export%s\n",
            es->channel >= 0 ? " (one channel: every colour grey)" : "");
    fprintf(f, "# render: blender -b --factory-startup -P THIS.py -- IMAGE.exr (or .pfm)\n\n");
    for (size_t i = 0; i < sizeof PREAMBLE / sizeof PREAMBLE[0]; i++)
        fprintf(f, "%s\n", PREAMBLE[i]);
    fprintf(f, "\n# ---- the scene ----\n\nsettings(%d, %d, %d)\n", es->width, es->height,
            es->spp);
    int shift = (int)ceil(log2(reach(es)));
    fprintf(f, "# Blender's unit is 2^%d of ours: the scene fits in a unit, where Cycles 3.4 "
               "samples\n# triangle lights by area (exact), not by its approximate solid "
               "angle\nUNIT = %.17g\n", shift, ldexp(1.0, -shift));
    write_camera(f, es);
    write_lights(f, es);
    for (size_t i = 0; i < es->n_materials; i++)
        if (es->material_used[i])
            write_material(f, es, i);
    struct emitters lit = {xmalloc(es->n_spheres + 1, sizeof *lit.index, "spheres"), 0};
    for (size_t i = 0; i < es->n_spheres; i++)
        if (material_emits(&es->materials[es->spheres[i].material]))
            lit.index[lit.n++] = i;
    for (size_t k = 0; k < es->n_materials; k++)
        write_spheres(f, es, &lit, (int)k);
    xfree(lit.index);
    for (size_t i = 0; i < es->n_meshes; i++)
        write_mesh(f, i, &es->meshes[i]);
    fprintf(f, "\nrender()\n");
    return 0;
}
