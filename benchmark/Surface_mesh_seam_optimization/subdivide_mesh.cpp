// Makes the large meshes of the scaling benchmark: Loop subdivision (each
// step multiplies the number of faces by 4; the boundary is subdivided too,
// so a disk stays a disk) of a Surface_mesh, written as OBJ.
//
// Usage: subdivide_mesh in.obj out.obj steps
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;

int main(int argc, char** argv)
{
  if(argc != 4)
  {
    std::cerr << "usage: " << argv[0] << " in.obj out.obj steps\n";
    return EXIT_FAILURE;
  }
  Surface_mesh sm;
  if(!CGAL::IO::read_polygon_mesh(argv[1], sm) || is_empty(sm) || !CGAL::is_triangle_mesh(sm))
  {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  const int steps = std::atoi(argv[3]);
  const std::size_t faces_before = sm.number_of_faces();
  CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(steps));
  if(sm.number_of_faces() != faces_before << (2 * steps))
  {
    std::cerr << "unexpected face count " << sm.number_of_faces() << "\n";
    return EXIT_FAILURE;
  }
  if(!CGAL::IO::write_polygon_mesh(argv[2], sm, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "cannot write " << argv[2] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << faces_before << " -> " << sm.number_of_faces() << " faces\n";
  return EXIT_SUCCESS;
}
