// Point samples of the surface of a molecule, for the conformal_curvature
// program (example code, not part of the library).
//
// 1. read_pdb(path) reads the ATOM and HETATM records of a Protein Data Bank
//    file (fixed columns of the PDB format, version 3.3):
//      columns 13-16 atom name, 17 alternate location, 18-20 residue name,
//      31-38, 39-46, 47-54 x, y, z in angstroms, 77-78 element symbol.
//      22 chain, 23-26 residue number, 27 insertion code.
//    The element comes from columns 77-78 when they hold letters. Old files
//    (before format 2.0) hold the entry's code and a line number in columns
//    73-80 ("1HPV 186"): when columns 77-80 are digits and blanks, or when
//    77-78 are blank, the element comes from the atom name by the PDB
//    convention: a one-letter element sits in column 14 (" CA " is a
//    carbon), a two-letter element starts in column 13 ("FE  ", "CA  " in a
//    HETATM record is calcium), and four-character names start in column 13
//    ("HG11" is a hydrogen). Without an element column, a HETATM name with
//    letters in columns 13-14 is a two-letter element when they name one of
//    the metals and halogens found in structures (FE, CA, ZN, CL, ...) and
//    do not start with H or D ("HG  " mercury needs columns 77-78); else the
//    letter in column 13 ("PE  " a phosphorus).
//    Kept: one model (the first, or the one asked for by its MODEL serial
//    number; a file without MODEL records is model 1); reading stops at
//    its ENDMDL or at END. Of the atoms of a residue (chain, number and
//    insertion code) with alternate locations, those with a blank location
//    or the residue's first location seen (usually 'A'). HETATM records are
//    kept unless asked (Pdb_options::keep_hetatm); chains can be selected
//    (Pdb_options::chains, "AB": chains A and B). Left out unless asked:
//    hydrogens (H, D) and waters (residue HOH, WAT, H2O, DOD, SOL).
//    A malformed record (too short for its coordinates, a coordinate that is
//    not a number, an element column that is neither letters nor a line
//    number, no element at all) throws cas3::Read_error, a
//    std::runtime_error, whose one-line message names the file and the line:
//    "1crn.pdb:57: ...". So does a model or chains that the file lacks.
//
// 2. bondi_radius(element): the van der Waals radius in angstroms, from
//    A. Bondi, "van der Waals Volumes and Radii", J. Phys. Chem. 68 (1964)
//    441-451 (table 12 there):
//      H 1.20  He 1.40  Li 1.82  C 1.70  N 1.55  O 1.52  F 1.47  Ne 1.54
//      Na 2.27 Mg 1.73  Si 2.10  P 1.80  S 1.80  Cl 1.75 Ar 1.88  K 2.75
//      Ni 1.63 Cu 1.40  Zn 1.39  Ga 1.87 As 1.85 Se 1.90 Br 1.85  Kr 2.02
//      Pd 1.63 Ag 1.72  Cd 1.58  In 1.93 Sn 2.17 Te 2.06 I 1.98   Xe 2.16
//      Pt 1.72 Au 1.66  Hg 1.55  Tl 1.96 Pb 2.02 U 1.86  (D as H)
//    Elements without a Bondi radius (Fe, Ca, Mn, ...) get
//    Pdb_options::default_radius, 2.0 A unless set (the default the
//    Cambridge Structural Database gives elements without a Bondi radius);
//    with a default radius of 0 they are an error.
//
// 3. Two samplings of a surface around the atoms (all lengths in angstroms):
//    - sample_skin_surface(): the skin surface (CGAL Skin_surface_3) of the
//      atoms' van der Waals balls, shrink factor 0.35 by default. It is a
//      smooth (tangent-continuous) closed surface made of patches of the
//      atoms' van der Waals spheres (where an atom is exposed) joined by
//      patches of hyperboloids and of inward spheres over the crevices
//      between atoms (Edelsbrunner, "Deformable smooth surface design",
//      1999): a smooth stand-in for the molecular (solvent-excluded)
//      surface. The balls are grown by CGAL (weights r^2 / s) so that the
//      sphere patches have the van der Waals radii; the smaller the shrink
//      factor s, the more the blends fill the crevices: on crambin, s = 0.35
//      keeps 95% of the points within 0.32 A of the solvent-excluded surface
//      of a 1.4 A probe (s = 0.5: 2.4 A, as it dips into the crevices). The
//      points are vertices of CGAL's skin mesh, subdivided until its mean
//      edge is below half the spacing, so they lie on the skin; normals are
//      the gradient of the skin's quadric at the point, outward. Cavities
//      (closed components of the skin inside the molecule) are left out
//      unless asked.
//    - sample_atom_spheres(): points of the atoms' spheres of radius
//      r + probe (probe 0: the van der Waals surface; probe 1.4: the
//      solvent-accessible surface) that are inside no other such ball, with
//      radial normals. Cheap and exact, but the surface has sharp concave
//      creases where spheres meet and no point inside the crevices.
//    Both are thinned to a minimum spacing: no two kept points are closer
//    than `spacing`, and every point of the dense sample lies within
//    `spacing` of a kept one (a greedy Poisson-disk thinning in a fixed
//    pseudo-random order, so that the result is reproducible).
//    The manual's section "Molecular surfaces" gives the measured times,
//    counts and smoothness of both on crambin (1crn).
#ifndef CAS3_MOLECULAR_SURFACE_H
#define CAS3_MOLECULAR_SURFACE_H

#include "cas3_read_point_cloud.h"  // cas3::Read_error and the line reader

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Skin_surface_3.h>
#include <CGAL/Skin_surface_polyhedral_items_3.h>
#include <CGAL/Skin_surface_traits_3.h>
#include <CGAL/mesh_skin_surface_3.h>
#include <CGAL/subdivide_skin_surface_mesh_3.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace cas3 {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Molecule_kernel;

struct Atom
{
  Molecule_kernel::Point_3 center;
  double radius = 0;    // van der Waals radius (angstroms)
  std::string element;  // upper case: "C", "FE"
  std::string name;     // atom name, trimmed: "CA"
  std::string residue;  // residue name, trimmed: "THR"
  char chain = ' ';     // chain identifier (column 22)
  bool hetatm = false;  // a HETATM record
  bool default_radius = false;  // no Bondi radius: Pdb_options::default_radius
  std::size_t line = 0; // line in the file
};

struct Pdb_options
{
  bool keep_hydrogens = false;
  bool keep_water = false;
  bool keep_hetatm = true;
  double default_radius = 2.0;  // for elements without a Bondi radius; 0: error
  int model = 0;                // MODEL serial number; 0: the first model
  std::string chains;           // chain identifiers to keep ("AB"); empty: all
};

// The Bondi van der Waals radius of an element ("C", "Cl" or "CL"), or 0
// when the table above has none.
inline double bondi_radius(std::string element)
{
  struct Entry { const char* element; double radius; };
  static const Entry table[] = {
    {"H", 1.20}, {"D", 1.20}, {"HE", 1.40}, {"LI", 1.82}, {"C", 1.70}, {"N", 1.55}, {"O", 1.52},
    {"F", 1.47}, {"NE", 1.54}, {"NA", 2.27}, {"MG", 1.73}, {"SI", 2.10}, {"P", 1.80}, {"S", 1.80},
    {"CL", 1.75}, {"AR", 1.88}, {"K", 2.75}, {"NI", 1.63}, {"CU", 1.40}, {"ZN", 1.39}, {"GA", 1.87},
    {"AS", 1.85}, {"SE", 1.90}, {"BR", 1.85}, {"KR", 2.02}, {"PD", 1.63}, {"AG", 1.72}, {"CD", 1.58},
    {"IN", 1.93}, {"SN", 2.17}, {"TE", 2.06}, {"I", 1.98}, {"XE", 2.16}, {"PT", 1.72}, {"AU", 1.66},
    {"HG", 1.55}, {"TL", 1.96}, {"PB", 2.02}, {"U", 1.86}};
  std::transform(element.begin(), element.end(), element.begin(),
                 [](unsigned char c) { return char(std::toupper(c)); });
  for(const Entry& e : table)
    if(element == e.element)
      return e.radius;
  return 0;
}

namespace molecule_detail {

inline std::string trimmed(const std::string& s)
{
  const std::size_t b = s.find_first_not_of(' ');
  if(b == std::string::npos)
    return std::string();
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

inline std::string upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  return s;
}

// Columns first..last (1-based, inclusive) of a line, blank-padded.
inline std::string columns(const std::string& line, std::size_t first, std::size_t last)
{
  std::string s = first <= line.size() ? line.substr(first - 1, last - first + 1) : std::string();
  s.resize(last - first + 1, ' ');
  return s;
}

inline bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// The element from the atom name (columns 13-16), by the PDB convention.
inline std::string element_from_name(const std::string& name, bool hetatm)
{
  const char c13 = name[0], c14 = name[1];
  if(!is_letter(c13))
    return is_letter(c14) ? upper(std::string(1, c14)) : std::string();
  // a letter in column 13: a two-letter element of a HETATM record ("FE  ",
  // "CA  " calcium), else a four-character name ("HG11" a hydrogen, "C10A")
  if(hetatm && is_letter(c14) && c13 != 'H' && c13 != 'h' && c13 != 'D' && c13 != 'd')
  {
    // the metals and halogens of ligands and ions
    static const char* const two_letter[] = {
      "LI", "NA", "MG", "AL", "SI", "CL", "AR", "CA", "SC", "TI", "CR", "MN", "FE", "CO", "NI", "CU", "ZN",
      "GA", "GE", "AS", "SE", "BR", "KR", "RB", "SR", "ZR", "MO", "RU", "RH", "PD", "AG", "CD", "IN", "SN",
      "SB", "TE", "XE", "CS", "BA", "LA", "CE", "GD", "YB", "LU", "HF", "TA", "RE", "OS", "IR", "PT", "AU",
      "TL", "PB", "BI"};
    const std::string guess = upper(std::string{c13, c14});
    for(const char* e : two_letter)
      if(guess == e)
        return guess;
  }
  return upper(std::string(1, c13));
}

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

inline bool is_water(const std::string& residue)
{
  return residue == "HOH" || residue == "WAT" || residue == "H2O" || residue == "DOD" || residue == "SOL";
}

} // namespace molecule_detail

// Parses the text of a PDB file; `name` prefixes the messages.
inline std::vector<Atom> parse_pdb(const std::string& text, const std::string& name,
                                   const Pdb_options& options = Pdb_options())
{
  using namespace molecule_detail;
  std::vector<Atom> atoms;
  read_detail::Lines lines(text);
  std::string line;
  // the first alternate location seen in each residue (chain, number, insertion code)
  std::unordered_map<std::string, char> first_alternate;
  std::size_t records = 0, in_model = 0;
  std::string chains_seen, models_seen;
  int model = 0;                 // the current MODEL serial number; 0 before any
  bool reading = options.model <= 1;  // no MODEL record yet: the file's model 1
  bool found_model = false;
  while(lines.next(line))
  {
    const std::string record = columns(line, 1, 6);
    if(trimmed(record) == "END")
      break;
    if(record == "MODEL ")
    {
      const std::string serial = trimmed(columns(line, 11, 14));
      model = serial.empty() ? model + 1 : int(read_detail::number(serial, name + ":" + std::to_string(lines.number())
                                                                           + ": MODEL serial number (columns 11-14)"));
      models_seen += (models_seen.empty() ? "" : ", ") + std::to_string(model);
      reading = options.model == 0 ? !found_model : model == options.model;
      found_model = found_model || reading;
      continue;
    }
    if(record == "ENDMDL")
    {
      if(reading)
        break;
      continue;
    }
    const bool hetatm = record == "HETATM";
    if(record != "ATOM  " && !hetatm)
      continue;
    ++records;
    if(!reading)
      continue;
    ++in_model;
    const std::string where = name + ":" + std::to_string(lines.number());
    if(line.size() < 54)
      throw Read_error(where + ": " + trimmed(record) + " record too short: " + std::to_string(line.size())
                       + " characters, the coordinates need columns 31-54");
    Atom atom;
    atom.line = lines.number();
    atom.hetatm = hetatm;
    atom.name = trimmed(columns(line, 13, 16));
    atom.residue = trimmed(columns(line, 18, 20));
    atom.chain = columns(line, 22, 22)[0];
    double xyz[3];
    for(int k = 0; k < 3; ++k)
    {
      const std::string field = trimmed(columns(line, 31 + 8 * std::size_t(k), 38 + 8 * std::size_t(k)));
      if(field.empty())
        throw Read_error(where + ": " + "xyz"[k] + " coordinate (columns " + std::to_string(31 + 8 * k) + "-"
                         + std::to_string(38 + 8 * k) + ") is blank");
      xyz[k] = read_detail::number(field, where + ": " + "xyz"[k] + " coordinate (columns "
                                              + std::to_string(31 + 8 * k) + "-" + std::to_string(38 + 8 * k) + ")");
    }
    atom.center = Molecule_kernel::Point_3(xyz[0], xyz[1], xyz[2]);

    const std::string symbol = trimmed(columns(line, 77, 78));
    const std::string tail = columns(line, 77, 80);
    // columns 73-80 of old files: the entry's code and a line number
    const bool line_number = std::all_of(tail.begin(), tail.end(), [](char c) { return c == ' ' || is_digit(c); });
    if(!symbol.empty() && !line_number)
    {
      if(!std::all_of(symbol.begin(), symbol.end(), [](char c) { return is_letter(c); }))
        throw Read_error(where + ": element symbol (columns 77-78) is not letters: '" + read_detail::shown(symbol)
                         + "'");
      atom.element = upper(symbol);
    }
    else
    {
      atom.element = element_from_name(columns(line, 13, 16), hetatm);
      if(atom.element.empty())
        throw Read_error(where + ": no element: columns 77-78 " + (symbol.empty() ? "are blank" : "hold a line number")
                         + " and the atom name '" + read_detail::shown(atom.name)
                         + "' (columns 13-16) does not give one");
    }

    if(chains_seen.find(atom.chain) == std::string::npos)
      chains_seen += atom.chain;
    if(!options.chains.empty() && options.chains.find(atom.chain) == std::string::npos)
      continue;
    if(!options.keep_hetatm && hetatm)
      continue;
    // alternate locations: the blank one and the residue's first one seen
    const char alternate = columns(line, 17, 17)[0];
    if(alternate != ' ')
    {
      const char first = first_alternate.emplace(columns(line, 22, 27), alternate).first->second;
      if(alternate != first)
        continue;
    }
    if(!options.keep_hydrogens && (atom.element == "H" || atom.element == "D"))
      continue;
    if(!options.keep_water && is_water(atom.residue))
      continue;
    atom.radius = bondi_radius(atom.element);
    if(!(atom.radius > 0))
    {
      if(!(options.default_radius > 0))
        throw Read_error(where + ": no Bondi radius for element '" + read_detail::shown(atom.element)
                         + "' (give a default radius)");
      atom.radius = options.default_radius;
      atom.default_radius = true;
    }
    atoms.push_back(atom);
  }
  if(records == 0)
    throw Read_error(name + ": no ATOM or HETATM record: not a PDB file?");
  if(options.model > 0 && in_model == 0)
    throw Read_error(name + ": no model " + std::to_string(options.model) + " (models in the file: "
                     + (models_seen.empty() ? std::string("1, without MODEL records") : models_seen) + ")");
  if(atoms.empty() && !options.chains.empty())
  {
    std::string shown_chains;
    for(char c : chains_seen)
      shown_chains += std::string(shown_chains.empty() ? "" : ", ") + (c == ' ' ? std::string("blank") : std::string(1, c));
    throw Read_error(name + ": no atom kept in chain(s) '" + options.chains + "' (chains in the file: " + shown_chains
                     + ")");
  }
  if(atoms.empty())
    throw Read_error(name + ": every atom was left out (hydrogens, waters, HETATM records or alternate locations)");
  return atoms;
}

// Reads the PDB file `path`. Throws Read_error.
inline std::vector<Atom> read_pdb(const std::string& path, const Pdb_options& options = Pdb_options())
{
  return parse_pdb(read_detail::file_bytes(path), path, options);
}

// A point sample of a surface with outward unit normals; atom[i] is the atom
// whose sphere holds point i (sample_atom_spheres) or the atom whose van der
// Waals sphere is nearest to it (sample_skin_surface).
struct Surface_sample
{
  std::vector<Molecule_kernel::Point_3> points;
  std::vector<Molecule_kernel::Vector_3> normals;
  std::vector<std::size_t> atom;
};

namespace molecule_detail {

typedef Molecule_kernel::Point_3 Point;
typedef Molecule_kernel::Vector_3 Vector;

// A uniform grid of cubes of side `cell` over points, for neighbor queries.
class Grid
{
public:
  explicit Grid(double cell) : m_cell(cell) {}
  std::array<std::int64_t, 3> key(const Point& p) const
  {
    return {std::int64_t(std::floor(p.x() / m_cell)), std::int64_t(std::floor(p.y() / m_cell)),
            std::int64_t(std::floor(p.z() / m_cell))};
  }
  void insert(const Point& p, std::size_t index) { m_cells[pack(key(p))].push_back(index); }
  // Calls f(index) for every inserted point in the 27 cells around p, until
  // f returns true; returns whether it did.
  template <class F>
  bool any_near(const Point& p, F f) const
  {
    const std::array<std::int64_t, 3> k = key(p);
    for(std::int64_t dx = -1; dx <= 1; ++dx)
      for(std::int64_t dy = -1; dy <= 1; ++dy)
        for(std::int64_t dz = -1; dz <= 1; ++dz)
        {
          const auto it = m_cells.find(pack({k[0] + dx, k[1] + dy, k[2] + dz}));
          if(it != m_cells.end())
            for(std::size_t i : it->second)
              if(f(i))
                return true;
        }
    return false;
  }

private:
  static std::uint64_t pack(const std::array<std::int64_t, 3>& k)
  {
    return (std::uint64_t(k[0] & 0x1fffff) << 42) | (std::uint64_t(k[1] & 0x1fffff) << 21)
           | std::uint64_t(k[2] & 0x1fffff);
  }
  double m_cell;
  std::unordered_map<std::uint64_t, std::vector<std::size_t> > m_cells;
};

// Greedy Poisson-disk thinning: visits the points in a pseudo-random order
// of fixed seed and keeps a point when no kept point is closer than spacing.
// The shuffle starts from the points sorted by their coordinates, so the
// sample does not depend on the order in which the mesher gave them (which
// follows memory addresses).
inline Surface_sample thin(const Surface_sample& dense, double spacing)
{
  std::vector<std::size_t> order(dense.points.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return CGAL::compare_xyz(dense.points[i], dense.points[j]) == CGAL::SMALLER;
  });
  std::mt19937_64 random(20240611);  // Fisher-Yates with a fixed engine: the same order everywhere
  for(std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[std::size_t(random() % i)]);
  Grid grid(spacing);
  Surface_sample kept;
  const double squared = spacing * spacing;
  for(std::size_t i : order)
  {
    const Point& p = dense.points[i];
    if(grid.any_near(p, [&](std::size_t j) { return CGAL::squared_distance(p, kept.points[j]) < squared; }))
      continue;
    grid.insert(p, kept.points.size());
    kept.points.push_back(p);
    kept.normals.push_back(dense.normals[i]);
    kept.atom.push_back(dense.atom[i]);
  }
  return kept;
}

} // namespace molecule_detail

// Points of the spheres of radius r + probe around the atoms that lie in no
// other such ball, thinned to `spacing`; normals radial.
inline Surface_sample sample_atom_spheres(const std::vector<Atom>& atoms, double probe, double spacing)
{
  using namespace molecule_detail;
  double largest = 0;
  for(const Atom& a : atoms)
    largest = (std::max)(largest, a.radius + probe);
  Grid centers(2 * largest);
  for(std::size_t i = 0; i < atoms.size(); ++i)
    centers.insert(atoms[i].center, i);
  Surface_sample dense;
  const double golden_angle = CGAL_PI * (3 - std::sqrt(5.0));
  for(std::size_t i = 0; i < atoms.size(); ++i)
  {
    const double R = atoms[i].radius + probe;
    // a Fibonacci lattice about twice as dense as the spacing asks
    const std::size_t n = std::size_t(std::ceil(4 * CGAL_PI * R * R / (0.25 * spacing * spacing))) + 1;
    for(std::size_t k = 0; k < n; ++k)
    {
      const double z = 1 - (2 * double(k) + 1) / double(n);
      const double s = std::sqrt((std::max)(0.0, 1 - z * z));
      const Vector u(s * std::cos(golden_angle * double(k)), s * std::sin(golden_angle * double(k)), z);
      const Point p = atoms[i].center + R * u;
      const bool buried = centers.any_near(p, [&](std::size_t j) {
        const double Rj = atoms[j].radius + probe;
        return j != i && CGAL::squared_distance(p, atoms[j].center) < Rj * Rj;
      });
      if(buried)
        continue;
      dense.points.push_back(p);
      dense.normals.push_back(u);
      dense.atom.push_back(i);
    }
  }
  return thin(dense, spacing);
}

// The skin surface of the atoms (shrink factor `shrink`, the van der Waals
// spheres being its sphere patches) as a CGAL polyhedron, and a sample of it.
struct Skin_surface_sample
{
  typedef CGAL::Skin_surface_traits_3<Molecule_kernel> Traits;
  typedef CGAL::Skin_surface_3<Traits> Skin;
  typedef CGAL::Polyhedron_3<Molecule_kernel, CGAL::Skin_surface_polyhedral_items_3<Skin> > Mesh;

  Mesh mesh;              // the subdivided skin mesh, the reference surface
  Surface_sample sample;  // its vertices, thinned
  int subdivisions = 0;
  std::size_t number_of_parts = 0;     // components of the outer surface
  std::size_t number_of_cavities = 0;  // components erased (or kept) as cavities
};

// Labels the connected components of a closed triangle polyhedron, and
// erases those whose signed volume has the opposite sign of the component
// of largest volume (cavities) unless `keep`. Returns +1 when the facets are
// oriented outward, -1 when inward.
template <class Mesh>
double remove_cavities(Mesh& mesh, bool keep, std::size_t& number_of_parts, std::size_t& number_of_cavities)
{
  typedef typename Mesh::Facet_handle Facet_handle;
  typedef typename Mesh::Halfedge_handle Halfedge_handle;
  std::unordered_map<const void*, std::size_t> component;
  std::vector<Halfedge_handle> representative;
  std::vector<double> volume6;
  for(auto f = mesh.facets_begin(); f != mesh.facets_end(); ++f)
  {
    if(component.count(&*f))
      continue;
    const std::size_t c = representative.size();
    representative.push_back(f->halfedge());
    volume6.push_back(0);
    std::vector<Facet_handle> stack(1, f);
    component[&*f] = c;
    while(!stack.empty())
    {
      const Facet_handle g = stack.back();
      stack.pop_back();
      Halfedge_handle h = g->halfedge();
      const auto& a = h->vertex()->point();
      const auto& b = h->next()->vertex()->point();
      const auto& d = h->next()->next()->vertex()->point();
      volume6[c] += CGAL::scalar_product(a - CGAL::ORIGIN, CGAL::cross_product(b - CGAL::ORIGIN, d - CGAL::ORIGIN));
      do
      {
        if(!h->opposite()->is_border())
        {
          const Facet_handle n = h->opposite()->facet();
          if(component.emplace(&*n, c).second)
            stack.push_back(n);
        }
        h = h->next();
      } while(h != g->halfedge());
    }
  }
  std::size_t largest = 0;
  for(std::size_t c = 0; c < volume6.size(); ++c)
    if(std::abs(volume6[c]) > std::abs(volume6[largest]))
      largest = c;
  const double outward = volume6.empty() || volume6[largest] >= 0 ? 1 : -1;
  number_of_cavities = 0;
  number_of_parts = 0;
  for(std::size_t c = 0; c < volume6.size(); ++c)
    if(outward * volume6[c] >= 0)
      ++number_of_parts;
    else
    {
      ++number_of_cavities;
      if(!keep)
        mesh.erase_connected_component(representative[c]);
    }
  return outward;
}

// The atom whose van der Waals sphere is nearest to p.
inline std::size_t nearest_sphere(const std::vector<Atom>& atoms, const Molecule_kernel::Point_3& p)
{
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < atoms.size(); ++i)
  {
    const double d = std::abs(std::sqrt(CGAL::squared_distance(p, atoms[i].center)) - atoms[i].radius);
    if(d < best)
    {
      best = d;
      nearest = i;
    }
  }
  return nearest;
}

// Mean edge length of a polyhedron.
template <class Mesh>
double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  std::size_t n = 0;
  for(auto e = mesh.edges_begin(); e != mesh.edges_end(); ++e, ++n)
    sum += std::sqrt(CGAL::squared_distance(e->vertex()->point(), e->opposite()->vertex()->point()));
  return n == 0 ? 0 : sum / double(n);
}

// Samples the skin surface (shrink factor `shrink`) of the atoms' van der
// Waals balls: the mesh is
// subdivided (at most 6 times, each sqrt(3) subdivision dividing its edges
// by about 1.7) until its mean edge is below spacing / 2, then its vertices
// are thinned to `spacing`. Normals: the gradient of the skin at the vertex.
inline void sample_skin_surface(const std::vector<Atom>& atoms, double spacing, Skin_surface_sample& result,
                                bool keep_cavities = false, double shrink = 0.35)
{
  using namespace molecule_detail;
  typedef Skin_surface_sample::Skin Skin;
  typedef Skin_surface_sample::Traits::Weighted_point_3 Weighted_point;
  std::vector<Weighted_point> balls;
  for(const Atom& a : atoms)
    balls.emplace_back(a.center, a.radius * a.radius);
  // grow_balls: the weights are divided by the shrink factor first, so that
  // an isolated atom's skin is its van der Waals sphere
  const Skin skin(balls.begin(), balls.end(), shrink, true);
  result.mesh.clear();
  CGAL::mesh_skin_surface_3(skin, result.mesh);
  result.subdivisions = 0;
  while(result.subdivisions < 6 && mean_edge_length(result.mesh) > spacing / 2)
  {
    CGAL::subdivide_skin_surface_mesh_3(skin, result.mesh, 1);
    ++result.subdivisions;
  }

  // the outward side, and the cavities: the connected components of the
  // mesh, each with its signed volume; the largest in absolute value is the
  // outer surface of the molecule (or of its largest piece) and tells the
  // outward orientation. Components of the opposite sign bound cavities
  // inside the molecule: they are erased, unless keep_cavities.
  const double outward = remove_cavities(result.mesh, keep_cavities, result.number_of_parts, result.number_of_cavities);
  Surface_sample dense;
  CGAL::Cartesian_converter<Molecule_kernel, Skin::Geometric_traits::Kernel> to_skin;
  CGAL::Cartesian_converter<Skin::Geometric_traits::Kernel, Molecule_kernel> from_skin;
  for(auto v = result.mesh.vertices_begin(); v != result.mesh.vertices_end(); ++v)
  {
    const Point& p = v->point();
    // the mesh normal (area weighted), to orient the gradient
    Vector around = CGAL::NULL_VECTOR;
    auto h = v->vertex_begin();
    do
    {
      if(!h->is_border())
      {
        const Point& a = h->vertex()->point();
        const Point& b = h->next()->vertex()->point();
        const Point& c = h->next()->next()->vertex()->point();
        around = around + CGAL::cross_product(b - a, c - a);
      }
    } while(++h != v->vertex_begin());
    around = outward * around;
    Vector n = from_skin(skin.normal(to_skin(p), v->halfedge()->facet()->tmc_ch));
    const double length = std::sqrt(n.squared_length());
    if(!(length > 0))
      n = around / std::sqrt(around.squared_length());
    else
      n = (CGAL::scalar_product(n, around) < 0 ? -1.0 : 1.0) * n / length;
    dense.points.push_back(p);
    dense.normals.push_back(n);
    dense.atom.push_back(0);
  }
  result.sample = thin(dense, spacing);
  for(std::size_t k = 0; k < result.sample.points.size(); ++k)
    result.sample.atom[k] = nearest_sphere(atoms, result.sample.points[k]);
}

} // namespace cas3

#endif // CAS3_MOLECULAR_SURFACE_H
