#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/OrderingMethods>
#include <Eigen/CholmodSupport>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <random>
#include <vector>
#include <algorithm>
typedef Eigen::SparseMatrix<double> SpMat;
typedef std::chrono::steady_clock Clock;
double secs(Clock::time_point a){return std::chrono::duration<double>(Clock::now()-a).count();}

// 2x2 block up-looking LDL^T on node graph (given permuted upper pattern by node).
struct BlockLDLT {
  int n; // nodes
  std::vector<int> parent, Lp, Lnz; std::vector<int> Li; std::vector<double> Lx; // Lx: 4 per block, row-major L_ri
  std::vector<double> D; // 4 per node: inverse of D block? store D and Dinv
  std::vector<double> Dinv;
  // upper pattern of permuted node matrix: column k holds rows i<=k (blocks), values 4 per block (A_ik: rows of i, cols of k)
  std::vector<int> Up, Ui;
  void analyze(int nn, const std::vector<int>& up, const std::vector<int>& ui) {
    n=nn; Up=up; Ui=ui;
    parent.assign(n,-1); std::vector<int> flag(n), cnt(n,0);
    for(int k=0;k<n;++k){ flag[k]=k;
      for(int p=Up[k];p<Up[k+1];++p){ int i=Ui[p]; if(i<k){ for(;flag[i]!=k;i=parent[i]){ if(parent[i]==-1) parent[i]=k; cnt[i]++; flag[i]=k; } } } }
    Lp.assign(n+1,0); for(int k=0;k<n;++k) Lp[k+1]=Lp[k]+cnt[k];
    Li.resize(Lp[n]); Lx.resize(4*size_t(Lp[n])); D.resize(4*n); Dinv.resize(4*n); Lnz.assign(n,0);
    Y.assign(4*size_t(n),0.); pattern.resize(n); flag2.assign(n,-1);
  }
  std::vector<double> Y; std::vector<int> pattern, flag2;
  // Ax: 4 per entry of Up (block A_ik row-major: [a(i0,k0) a(i0,k1); a(i1,k0) a(i1,k1)])
  bool factorize(const std::vector<double>& Ax){
    std::fill(Lnz.begin(),Lnz.end(),0);
    for(int k=0;k<n;++k){
      int top=n; flag2[k]=k; double dk[4]={0,0,0,0};
      for(int p=Up[k];p<Up[k+1];++p){ int i=Ui[p]; const double* a=&Ax[4*size_t(p)];
        if(i==k){ dk[0]+=a[0];dk[1]+=a[1];dk[2]+=a[2];dk[3]+=a[3]; continue;}
        double* y=&Y[4*size_t(i)]; y[0]+=a[0];y[1]+=a[1];y[2]+=a[2];y[3]+=a[3];
        int len=0; for(;flag2[i]!=k;i=parent[i]){ pattern[len++]=i; flag2[i]=k; }
        while(len>0) pattern[--top]=pattern[--len]; }
      for(;top<n;++top){ int i=pattern[top];
        double* yp=&Y[4*size_t(i)]; double y0=yp[0],y1=yp[1],y2=yp[2],y3=yp[3]; yp[0]=yp[1]=yp[2]=yp[3]=0;
        int p2=Lp[i]+Lnz[i];
        for(int p=Lp[i];p<p2;++p){ const double* l=&Lx[4*size_t(p)]; double* r=&Y[4*size_t(Li[p])];
          r[0]-=l[0]*y0+l[1]*y2; r[1]-=l[0]*y1+l[1]*y3; r[2]-=l[2]*y0+l[3]*y2; r[3]-=l[2]*y1+l[3]*y3; }
        // L_ki = Yi^T Dinv_i
        const double* di=&Dinv[4*size_t(i)];
        double l0=y0*di[0]+y2*di[2], l1=y0*di[1]+y2*di[3], l2=y1*di[0]+y3*di[2], l3=y1*di[1]+y3*di[3];
        // D_k -= L_ki * Yi
        dk[0]-=l0*y0+l1*y2; dk[1]-=l0*y1+l1*y3; dk[2]-=l2*y0+l3*y2; dk[3]-=l2*y1+l3*y3;
        double* lo=&Lx[4*size_t(p2)]; lo[0]=l0;lo[1]=l1;lo[2]=l2;lo[3]=l3; Li[p2]=k; ++Lnz[i]; }
      double* d=&D[4*size_t(k)]; d[0]=dk[0]; d[1]=0.5*(dk[1]+dk[2]); d[2]=d[1]; d[3]=dk[3];
      double det=d[0]*d[3]-d[1]*d[2]; if(!(det!=0) || !std::isfinite(det)) return false;
      double* di=&Dinv[4*size_t(k)]; di[0]=d[3]/det; di[1]=-d[1]/det; di[2]=-d[2]/det; di[3]=d[0]/det;
    }
    return true;
  }
  void solve(std::vector<double>& x) const { // in place, x length 2n permuted
    for(int j=0;j<n;++j){ double a=x[2*j],b=x[2*j+1]; for(int p=Lp[j];p<Lp[j+1];++p){ const double* l=&Lx[4*size_t(p)]; int r=Li[p]; x[2*r]-=l[0]*a+l[1]*b; x[2*r+1]-=l[2]*a+l[3]*b; } }
    for(int j=0;j<n;++j){ const double* di=&Dinv[4*size_t(j)]; double a=x[2*j],b=x[2*j+1]; x[2*j]=di[0]*a+di[1]*b; x[2*j+1]=di[2]*a+di[3]*b; }
    for(int j=n-1;j>=0;--j){ double a=x[2*j],b=x[2*j+1]; for(int p=Lp[j];p<Lp[j+1];++p){ const double* l=&Lx[4*size_t(p)]; int r=Li[p]; a-=l[0]*x[2*r]+l[2]*x[2*r+1]; b-=l[1]*x[2*r]+l[3]*x[2*r+1]; } x[2*j]=a; x[2*j+1]=b; }
  }
};

int main(int argc,char**argv){
  std::ifstream in(argv[1]); std::string line; int nv=0; std::vector<std::array<int,3>> F;
  while(std::getline(in,line)){ if(line.size()>1&&line[0]=='v'&&line[1]==' ') ++nv; else if(line.size()>1&&line[0]=='f'){ std::istringstream ss(line.substr(2)); std::array<int,3> f; for(int a=0;a<3;++a){ std::string t; ss>>t; f[a]=std::stoi(t)-1;} F.push_back(f);} }
  std::mt19937 rng(1); std::normal_distribution<double> N(0,1);
  std::vector<Eigen::Triplet<double>> T;
  for(auto& f:F){ Eigen::Matrix<double,6,6> M; Eigen::Matrix<double,6,4> G; for(int i=0;i<6;++i)for(int j=0;j<4;++j)G(i,j)=N(rng); M=G*G.transpose();
    for(int a=0;a<3;++a)for(int b=0;b<3;++b)for(int c=0;c<2;++c)for(int d=0;d<2;++d) T.emplace_back(2*f[a]+c,2*f[b]+d,M(2*a+c,2*b+d)); }
  for(int i=0;i<2*nv;++i) T.emplace_back(i,i,1e-3);
  SpMat A(2*nv,2*nv); A.setFromTriplets(T.begin(),T.end()); SpMat L=A.triangularView<Eigen::Lower>();
  int reps=20;
  // Eigen scalar
  Eigen::SimplicialLDLT<SpMat,Eigen::Lower,Eigen::AMDOrdering<int>> s; auto t0=Clock::now(); s.analyzePattern(L); double ta=secs(t0);
  std::vector<double> tf; for(int r=0;r<reps;++r){ t0=Clock::now(); s.factorize(L); tf.push_back(secs(t0)); }
  std::sort(tf.begin(),tf.end());
  Eigen::VectorXd b=Eigen::VectorXd::Random(2*nv); Eigen::VectorXd xs=s.solve(b);
  printf("scalar: n=%d analyze %.4f factorize median %.4f nnzL %ld\n",2*nv,ta,tf[reps/2],(long)s.matrixL().nestedExpression().nonZeros());
  // block: node graph AMD
  t0=Clock::now();
  std::vector<Eigen::Triplet<double>> TN; for(auto&f:F) for(int a=0;a<3;++a)for(int b2=0;b2<3;++b2) TN.emplace_back(f[a],f[b2],1.);
  SpMat G(nv,nv); G.setFromTriplets(TN.begin(),TN.end());
  Eigen::PermutationMatrix<Eigen::Dynamic,Eigen::Dynamic,int> inv; SpMat GL=G.triangularView<Eigen::Lower>(); Eigen::AMDOrdering<int>()(GL.selfadjointView<Eigen::Lower>(),inv);
  std::vector<int> perm(nv); for(int k=0;k<nv;++k) perm[inv.indices()[k]]=k;
  // upper pattern of permuted node matrix with values from A
  std::vector<std::vector<std::pair<int,int>>> cols(nv); // (row node, original (i,j))
  for(int j=0;j<nv;++j) for(SpMat::InnerIterator it(G,j);it;++it){ int i=it.row(); int pi=perm[i],pj=perm[j]; if(pi<=pj) cols[pj].push_back({pi,i*nv+0}); }
  std::vector<int> Up(nv+1,0),Ui; std::vector<std::pair<int,int>> orig;
  for(int k=0;k<nv;++k){ std::sort(cols[k].begin(),cols[k].end()); Up[k+1]=Up[k]+cols[k].size(); for(auto&c:cols[k]) Ui.push_back(c.first); }
  // inverse perm
  std::vector<int> iperm(nv); for(int i=0;i<nv;++i) iperm[perm[i]]=i;
  std::vector<double> Ax(4*Ui.size());
  SpMat Af=A; // full
  for(int k=0;k<nv;++k) for(int p=Up[k];p<Up[k+1];++p){ int i=iperm[Ui[p]], j=iperm[k]; for(int c=0;c<2;++c)for(int d=0;d<2;++d) Ax[4*p+2*c+d]=Af.coeff(2*i+c,2*j+d); }
  BlockLDLT bl; bl.analyze(nv,Up,Ui); double tba=secs(t0);
  std::vector<double> tb; for(int r=0;r<reps;++r){ t0=Clock::now(); bool ok=bl.factorize(Ax); tb.push_back(secs(t0)); if(!ok) printf("fail\n"); }
  std::sort(tb.begin(),tb.end());
  std::vector<double> x(2*nv); for(int i=0;i<nv;++i){ x[2*perm[i]]=b[2*i]; x[2*perm[i]+1]=b[2*i+1]; }
  bl.solve(x); double err=0; for(int i=0;i<nv;++i) for(int c=0;c<2;++c) err=std::max(err,std::abs(x[2*perm[i]+c]-xs[2*i+c]));
  { Eigen::CholmodSupernodalLLT<SpMat,Eigen::Lower> c; c.cholmod().nrelax[0]=12; c.cholmod().nrelax[1]=48; c.cholmod().nrelax[2]=144; c.cholmod().print=0;
    auto t1=Clock::now(); c.analyzePattern(L); double tca=secs(t1); std::vector<double> tc; for(int r=0;r<reps;++r){ t1=Clock::now(); c.factorize(L); tc.push_back(secs(t1)); } std::sort(tc.begin(),tc.end());
    printf("cholmod: analyze %.4f factorize median %.4f\n",tca,tc[reps/2]); }
  printf("block: analyze(incl setup) %.4f factorize median %.4f nnzL blocks %d (scalar equiv %d) maxdiff %.3g\n",tba,tb[reps/2],bl.Lp[nv],4*bl.Lp[nv]+nv,err);
}
