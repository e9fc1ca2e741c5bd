// Throughput of one process; run 1 copy, then 2 copies at once.
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(){struct timespec t;clock_gettime(CLOCK_MONOTONIC,&t);return t.tv_sec+1e-9*t.tv_nsec;}
int main(int argc,char**argv){
  int mode=atoi(argv[1]);
  double t0=now(); double s=0;
  if(mode==0){ // FP bound: independent FMA chains
    double a[8]={1,1.1,1.2,1.3,1.4,1.5,1.6,1.7};
    for(long i=0;i<400000000L;i++) for(int k=0;k<8;k++) a[k]=a[k]*0.9999999+1e-7;
    for(int k=0;k<8;k++) s+=a[k];
  } else { // memory bound: stream triad on 400 MB arrays
    long n=50000000L; double*x=malloc(n*8),*y=malloc(n*8),*z=malloc(n*8);
    for(long i=0;i<n;i++){x[i]=i;y[i]=1;z[i]=0;}
    t0=now();
    for(int r=0;r<10;r++) for(long i=0;i<n;i++) z[i]=x[i]+1.5*y[i];
    s=z[n/2];
  }
  printf("mode %d: %.3f s (%g)\n",mode,now()-t0,s);
}
