// The boundary mesh on the GPU (see DeviceMesh.cuh).
#include "cuda/DeviceMesh.cuh"

namespace parafluid::sph::cuda
{
namespace
{
constexpr int kThreads = 128;

template<class T>
void uploadTo(DeviceBuffer<T>& buffer, const std::vector<T>& values, cudaStream_t stream)
{
  buffer.upload(values.data(), values.size(), stream);
}

__global__ void findMeshWalls(const float* x, const float* y, const float* z, std::uint32_t n, TriangleMeshView mesh,
                              MeshContacts c)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n)
  {
    return;
  }
  const float p[3] = { x[i], y[i], z[i] };
  float distance, normal[3];
  std::uint32_t triangle = c.triangle[i];
  detail::findMeshWall(mesh, p, c.table.reach, distance, normal, triangle);
  c.distance[i] = distance;
  for (int d = 0; d < 3; ++d)
  {
    c.normal[static_cast<std::size_t>(d) * n + i] = normal[d];
  }
  c.triangle[i] = triangle;
}

__global__ void startWallSums(MeshContacts c, std::uint32_t n)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n)
  {
    c.wallSum[i] = c.table.at(c.distance[i]).sum;
  }
}
} // namespace

void DeviceMesh::upload(const TriangleBoundary& mesh, const detail::MeshWallTable* table, cudaStream_t stream)
{
  uploadTo(this->Points, mesh.points(), stream);
  uploadTo(this->VertexNormals, mesh.vertexNormals(), stream);
  uploadTo(this->FaceNormals, mesh.faceNormals(), stream);
  uploadTo(this->Triangles, mesh.triangles(), stream);
  uploadTo(this->CellStart, mesh.cellStart(), stream);
  uploadTo(this->CellTriangles, mesh.cellTriangles(), stream);
  this->View = TriangleMeshView{};
  this->View.points = this->Points.data();
  this->View.triangles = this->Triangles.data();
  this->View.vertexNormals = this->VertexNormals.data();
  this->View.faceNormals = this->FaceNormals.data();
  this->View.cellStart = this->CellStart.data();
  this->View.cellTriangles = this->CellTriangles.data();
  this->View.triangleCount = static_cast<std::uint32_t>(mesh.triangleCount());
  this->View.grid = mesh.grid();
  this->Table = detail::MeshWallTableView{};
  if (table && !table->empty())
  {
    uploadTo(this->Sum, table->sums(), stream);
    uploadTo(this->Slope, table->slopes(), stream);
    uploadTo(this->Count, table->counts(), stream);
    this->Table = table->view();
    this->Table.sum = this->Sum.data();
    this->Table.slope = this->Slope.data();
    this->Table.count = this->Count.data();
  }
}

std::size_t DeviceMesh::bytes() const
{
  return this->Points.bytes() + this->VertexNormals.bytes() + this->FaceNormals.bytes() + this->Sum.bytes() +
         this->Slope.bytes() + this->Count.bytes() + this->Triangles.bytes() + this->CellStart.bytes() +
         this->CellTriangles.bytes();
}

void launchFindMeshWalls(const float* x, const float* y, const float* z, std::uint32_t n, const TriangleMeshView& mesh,
                         const MeshContacts& c, cudaStream_t stream)
{
  if (n == 0)
    return;
  findMeshWalls<<<(n + kThreads - 1) / kThreads, kThreads, 0, stream>>>(x, y, z, n, mesh, c);
  check(cudaGetLastError(), "the mesh-wall kernel");
}

void launchStartWallSums(const MeshContacts& c, std::uint32_t n, cudaStream_t stream)
{
  if (n == 0)
    return;
  startWallSums<<<(n + kThreads - 1) / kThreads, kThreads, 0, stream>>>(c, n);
  check(cudaGetLastError(), "the wall-sum kernel");
}
} // namespace parafluid::sph::cuda
