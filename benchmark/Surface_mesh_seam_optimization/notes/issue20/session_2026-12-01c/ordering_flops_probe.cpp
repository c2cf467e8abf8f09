#include <cholmod.h>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <set>
#include <array>
#include <ctime>
#include <algorithm>
// vertex graph of an OBJ (faces) as a symmetric CHOLMOD pattern (lower), ordering stats
int main(int argc, char** argv)
{
  std::ifstream in(argv[1]);
  std::string line; int nv = 0; std::vector<std::array<int,3>> F;
  while(std::getline(in, line)) {
    if(line.size() > 2 && line[0]=='v' && line[1]==' ') ++nv;
    else if(line.size() > 2 && line[0]=='f' && line[1]==' ') {
      std::istringstream s(line.substr(2)); std::string t; int k=0; std::array<int,3> f;
      while(s >> t && k < 3) f[k++] = std::stoi(t.substr(0, t.find('/'))) - 1;
      F.push_back(f);
    }
  }
  std::vector<std::vector<int>> adj(nv);
  for(auto& f : F) for(int a=0;a<3;++a) for(int b=0;b<3;++b) if(a!=b) adj[f[a]].push_back(f[b]);
  cholmod_common c; cholmod_start(&c);
  size_t nnz = 0;
  for(int v=0; v<nv; ++v){ auto& a=adj[v]; a.push_back(v); std::sort(a.begin(),a.end()); a.erase(std::unique(a.begin(),a.end()),a.end()); for(int w: a) if(w>=v) ++nnz; }
  cholmod_sparse* A = cholmod_allocate_sparse(nv, nv, nnz, 1, 1, -1, CHOLMOD_REAL, &c);
  int* p = (int*)A->p; int* i = (int*)A->i; double* x = (double*)A->x; size_t q=0;
  for(int v=0; v<nv; ++v){ p[v]=q; for(int w: adj[v]) if(w>=v){ i[q]=w; x[q]= (w==v? 100.:-1.); ++q; } } p[nv]=q;
  const char* names[] = {"AMD","METIS","NESDIS"}; int ords[] = {CHOLMOD_AMD, CHOLMOD_METIS, CHOLMOD_NESDIS};
  for(int m=0;m<3;++m){
    c.nmethods = 1; c.method[0].ordering = ords[m]; c.postorder = 1; c.supernodal = CHOLMOD_SIMPLICIAL;
    double t0 = (double)clock();
    cholmod_factor* L = cholmod_analyze(A, &c);
    double t1 = (double)clock();
    std::printf("%s n=%d lnz=%.0f flops=%.3g  (x16 for 2x2 blocks)  analyze %.1f ms\n", names[m], nv, c.lnz, c.fl, 1000*(t1-t0)/CLOCKS_PER_SEC);
    cholmod_free_factor(&L, &c);
  }
  cholmod_finish(&c);
}
