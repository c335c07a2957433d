/**
 * @class   vtkCoarseGrainedMeshAdaptation
 * @brief   refine a tetrahedral mesh in parallel by running a serial kernel on coloured partitions
 *
 * The input (linear tetrahedra only) is partitioned with METIS into NumberOfPartitions parts, or,
 * with PartitionByRegion, along the regions of RegionArrayName into PartitionsPerRegion parts
 * each. The partition graph (partitions sharing a vertex) is coloured with ColoringAlgorithm, and
 * for each of NumberOfIterations passes the partitions of one colour are refined concurrently by
 * the serial kernel chosen with Method, and interface splits are handed to the neighbours that
 * follow.
 *
 * Template: edges longer than the threshold are split by conforming templates. The threshold is
 * MaximumEdgeLength when positive, else EdgeLengthFactor times the input's mean edge length.
 *
 * Delaunay: the volume bound V is MaximumVolume when positive, else VolumeFactor times the input's
 * mean tet volume. Partition-interface and material-interface edges are split by templates down
 * to the edge length of the regular tetrahedron of volume V, (6 sqrt(2) V)^(1/3); TetGen then
 * refines each partition's interior with its boundary faces kept (switches r, Y, q with
 * RadiusEdgeRatio, a with V). A partition on which TetGen fails is refined by templates instead,
 * with a warning naming it.
 *
 * With ImproveQuality (default on), each partition's tets are improved after refinement, in the
 * same colour loop: edge removal, 2->3 face swaps and Laplacian smoothing with rollback, applied to
 * tets whose mean ratio 12 (3V)^(2/3) / sum of squared edge lengths (1 = regular tetrahedron) is
 * below 0.5, and kept only when the worst mean ratio of the tets changed rises. Vertices on
 * partition interfaces, on the domain boundary and on material interfaces stay fixed. A second
 * sweep over box-shaped partitions that cut across the refinement partitions then improves the
 * tets around the former partition interfaces too.
 *
 * The output is one conforming tetrahedral grid. Input cell data is copied to every child cell and
 * input point data is interpolated linearly onto new points. The output also holds the cell arrays
 * PartitionId, ColorId, EdgeRatio and MinDihedralAngle (vtkMeshQuality, degrees) and
 * NearFormerInterface (vtkUnsignedCharArray, 1 for a tet touching a vertex that lay on an interface
 * between refinement partitions), and field data
 * with the colour, partition and thread counts, the (interface) edge length threshold, the method
 * (Method, by name), VolumeBound, DelaunayFallbacks, FallbackPartitions (one tuple per fallback)
 * and TetGenPoints (all 0 or empty for Template), the
 * colouring (ColoringAlgorithm, by name), the colour populations (PartitionsPerColor and
 * CellsPerColor, one tuple per colour), ColorBalance (largest colour over the mean, in partitions),
 * the improvement counts (EdgeRemovals, FaceSwaps, VertexMoves)
 * and the seconds spent per phase (PartitionSeconds, GraphSeconds, ColorSeconds, HealSeconds,
 * AdaptSeconds, PostSeconds, ImproveSeconds, MergeSeconds, QualitySeconds, TotalSeconds). The
 * output does not depend on NumberOfThreads.
 */
#ifndef vtkCoarseGrainedMeshAdaptation_h
#define vtkCoarseGrainedMeshAdaptation_h

#include "cgmeshFiltersModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <string> // for std::string

class vtkUnstructuredGrid;

class CGMESHFILTERS_EXPORT vtkCoarseGrainedMeshAdaptation : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkCoarseGrainedMeshAdaptation* New();
  vtkTypeMacro(vtkCoarseGrainedMeshAdaptation, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of METIS partitions; reduced (with a warning) when the mesh is too small. Default 1024.
   */
  vtkSetClampMacro(NumberOfPartitions, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfPartitions, int);
  ///@}

  ///@{
  /**
   * Number of refinement passes over all colours. Default 1.
   */
  vtkSetClampMacro(NumberOfIterations, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfIterations, int);
  ///@}

  /**
   * Serial refinement kernels run on the partitions.
   */
  enum Methods
  {
    TEMPLATE = 0, // split long edges by conforming templates
    DELAUNAY = 1  // templates on interfaces, TetGen inside partitions
  };

  ///@{
  /**
   * Refinement kernel, one of Methods. Default TEMPLATE.
   */
  vtkSetClampMacro(Method, int, TEMPLATE, DELAUNAY);
  vtkGetMacro(Method, int);
  void SetMethodToTemplate() { this->SetMethod(TEMPLATE); }
  void SetMethodToDelaunay() { this->SetMethod(DELAUNAY); }
  ///@}

  /**
   * Name of the current method: "template" or "delaunay" (the names of the command line's --method
   * option).
   */
  const char* GetMethodName() { return MethodToName(this->Method); }

  ///@{
  /**
   * Conversion between Methods values and their names; MethodToName returns nullptr for a value
   * out of range, MethodFromName returns -1 for an unknown name.
   */
  static const char* MethodToName(int method);
  static int MethodFromName(const char* name);
  ///@}

  ///@{
  /**
   * Template: edges longer than this absolute length are split. Not used when not positive (default
   * 0).
   */
  vtkSetMacro(MaximumEdgeLength, double);
  vtkGetMacro(MaximumEdgeLength, double);
  ///@}

  ///@{
  /**
   * Template: split threshold as a fraction of the input's mean edge length, used when
   * MaximumEdgeLength is not positive. Default 0.5.
   */
  vtkSetClampMacro(EdgeLengthFactor, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(EdgeLengthFactor, double);
  ///@}

  ///@{
  /**
   * Delaunay: TetGen's absolute volume bound (switch a). Not used when not positive (default 0).
   */
  vtkSetMacro(MaximumVolume, double);
  vtkGetMacro(MaximumVolume, double);
  ///@}

  ///@{
  /**
   * Delaunay: volume bound as a fraction of the input's mean tet volume, used when MaximumVolume
   * is not positive. Default 0.1.
   */
  vtkSetClampMacro(VolumeFactor, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(VolumeFactor, double);
  ///@}

  ///@{
  /**
   * Delaunay: TetGen's radius-edge ratio bound (switch q); smaller values ask for better tets and
   * more points. Clamped to at least 1. Default 2.
   */
  vtkSetClampMacro(RadiusEdgeRatio, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RadiusEdgeRatio, double);
  ///@}

  ///@{
  /**
   * Improve the tets after refinement (edge removal, face swaps, guarded smoothing; see the class
   * description), keeping partition-interface, domain-boundary and material-interface vertices
   * fixed. Default on.
   */
  vtkSetMacro(ImproveQuality, bool);
  vtkGetMacro(ImproveQuality, bool);
  vtkBooleanMacro(ImproveQuality, bool);
  ///@}

  ///@{
  /**
   * With ImproveQuality: sweeps of edge removal, face swaps and smoothing per partition, in each
   * of the two improvement sweeps. Clamped to [0, 20]. Default 2.
   */
  vtkSetClampMacro(NumberOfImprovementPasses, int, 0, 20);
  vtkGetMacro(NumberOfImprovementPasses, int);
  ///@}

  ///@{
  /**
   * Size guard: a refinement iteration forecast to produce more tetrahedra than this is refused
   * with an error (and an empty output) before anything large is allocated. 0 means no limit.
   * Default 100000000.
   */
  vtkSetClampMacro(MaximumNumberOfCells, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfCells, vtkIdType);
  ///@}

  ///@{
  /**
   * Number of OpenMP threads; 0 (default) uses all cores. The output does not depend on it.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /**
   * Colourings of the partition graph. Greedy (first fit) is unbalanced; Greedy-LU (least-used
   * permissible colour) balances the colour sets; Iterative (speculative parallel colouring with
   * conflict rounds) and Recoloring (parallel rebalancing of an initial colouring) use the
   * threads. Every algorithm gives the same colours for any number of threads.
   */
  enum ColoringAlgorithms
  {
    GREEDY = 0,
    GREEDY_LEAST_USED = 1,
    ITERATIVE = 2,
    RECOLORING = 3
  };

  ///@{
  /**
   * Colouring of the partition graph, one of ColoringAlgorithms. Default GREEDY_LEAST_USED.
   */
  vtkSetClampMacro(ColoringAlgorithm, int, GREEDY, RECOLORING);
  vtkGetMacro(ColoringAlgorithm, int);
  void SetColoringAlgorithmToGreedy() { this->SetColoringAlgorithm(GREEDY); }
  void SetColoringAlgorithmToGreedyLeastUsed() { this->SetColoringAlgorithm(GREEDY_LEAST_USED); }
  void SetColoringAlgorithmToIterative() { this->SetColoringAlgorithm(ITERATIVE); }
  void SetColoringAlgorithmToRecoloring() { this->SetColoringAlgorithm(RECOLORING); }
  ///@}

  /**
   * Name of the current colouring: "greedy", "greedy-lu", "iterative" or "recoloring" (the names
   * of the command line's --coloring option).
   */
  const char* GetColoringAlgorithmName()
  {
    return ColoringAlgorithmToName(this->ColoringAlgorithm);
  }

  ///@{
  /**
   * Conversion between ColoringAlgorithms values and their names; ColoringAlgorithmToName returns
   * nullptr for a value out of range, ColoringAlgorithmFromName returns -1 for an unknown name.
   */
  static const char* ColoringAlgorithmToName(int algorithm);
  static int ColoringAlgorithmFromName(const char* name);
  ///@}

  ///@{
  /**
   * Cut the mesh along the regions of RegionArrayName instead of METIS on the whole mesh: each
   * region becomes PartitionsPerRegion partitions, and NumberOfPartitions is not used. Needs
   * RegionArrayName (an error otherwise). Default off.
   */
  vtkSetMacro(PartitionByRegion, bool);
  vtkGetMacro(PartitionByRegion, bool);
  vtkBooleanMacro(PartitionByRegion, bool);
  ///@}

  ///@{
  /**
   * With PartitionByRegion: the number of METIS partitions each region is cut into. Default 1.
   */
  vtkSetClampMacro(PartitionsPerRegion, int, 1, VTK_INT_MAX);
  vtkGetMacro(PartitionsPerRegion, int);
  ///@}

  ///@{
  /**
   * Optional name of a numeric cell array holding material/region ids (converted to int). Unset,
   * empty or "None" (default; ParaView's "no array" choice) means a single region, unless the input
   * really has a cell array called "None". Any other name that is not a cell array of the input is
   * an error.
   */
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

protected:
  vtkCoarseGrainedMeshAdaptation();
  ~vtkCoarseGrainedMeshAdaptation() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // The region array name to use: empty when unset, empty or ParaView's "None" entry.
  std::string ResolveRegionArrayName(vtkUnstructuredGrid* input) const;
  // Reports an error and returns false unless every input cell is a linear tetrahedron and
  // PartitionByRegion has a region array to cut along.
  bool CheckInput(vtkUnstructuredGrid* input);

  int NumberOfPartitions;
  int NumberOfIterations;
  int Method;
  double MaximumEdgeLength;
  double EdgeLengthFactor;
  double MaximumVolume;
  double VolumeFactor;
  double RadiusEdgeRatio;
  int NumberOfThreads;
  char* RegionArrayName;
  int ColoringAlgorithm;
  bool PartitionByRegion;
  int PartitionsPerRegion;
  bool ImproveQuality;
  int NumberOfImprovementPasses;
  vtkIdType MaximumNumberOfCells;

private:
  vtkCoarseGrainedMeshAdaptation(const vtkCoarseGrainedMeshAdaptation&) = delete;
  void operator=(const vtkCoarseGrainedMeshAdaptation&) = delete;
};

#endif
