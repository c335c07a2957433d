/**
 * @class   vtkCoarseGrainedMeshAdaptation
 * @brief   refine a tetrahedral mesh in parallel by running a serial kernel on coloured partitions
 *
 * The input (linear tetrahedra, and triangles tagging boundary or material-interface faces of them)
 * is partitioned with METIS into NumberOfPartitions parts, or,
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
 * With ImproveQuality (default on), each Template partition's tets are improved after refinement,
 * in the same colour loop (Delaunay partitions, whose interiors TetGen made good, are left to the
 * sweeps below): edge removal, 2->3 face swaps and Laplacian smoothing with rollback, applied to
 * tets whose mean ratio 12 (3V)^(2/3) / sum of squared edge lengths (1 = regular tetrahedron) is
 * below 0.5, and kept only when the worst mean ratio of the tets changed rises. Vertices on
 * partition interfaces, on the domain boundary and on material interfaces stay fixed. A second
 * sweep over box-shaped partitions that cut across the refinement partitions then improves the
 * tets around the former partition interfaces too.
 *
 * The output is one conforming tetrahedral grid, followed by the children of the input's triangles
 * (each refined as the faces it lies on, oriented as it was). Input cell data is copied to every
 * child cell and input point data is interpolated linearly onto new points. The output also holds
 * the cell arrays PartitionId, ColorId, EdgeRatio and MinDihedralAngle (vtkMeshQuality, degrees)
 * and NearFormerInterface (vtkUnsignedCharArray, 1 for a tet touching a vertex that lay on an
 * interface between refinement partitions), and field data with the colour, partition and thread
 * counts, the (interface) edge length threshold, the method (MethodIndex), the partitioner used
 * (PartitionerIndex: METIS or HILBERT), VolumeBound, DelaunayFallbacks, TetGenPoints and
 * TetGenRetries (partitions whose first TetGen call failed and was made again with the tets in
 * reverse order; all 0 for Template), IterationsRun and RefinementConverged, the colouring
 * (ColoringAlgorithmIndex), and with Diagnostics also Method and ColoringAlgorithm by name and
 * FallbackPartitions (one tuple per fallback); the colour populations (PartitionsPerColor and
 * CellsPerColor, one tuple per colour), ColorBalance (largest colour over the mean, in partitions),
 * the improvement counts (EdgeRemovals, FaceSwaps, VertexMoves) and the seconds spent per phase
 * (PrepareSeconds, PartitionSeconds, GraphSeconds, ColorSeconds, HealSeconds, AdaptSeconds,
 * ImproveSeconds, PostSeconds, MergeSeconds; each second is charged to one phase only), and the
 * filter's own: InputSeconds (checking and converting the input), OutputSeconds (building the
 * output grid and its cell and point data), QualitySeconds (the quality arrays) and TotalSeconds.
 * Progress never decreases. The output does not depend on NumberOfThreads.
 */
#ifndef vtkCoarseGrainedMeshAdaptation_h
#define vtkCoarseGrainedMeshAdaptation_h

#include "cgmeshFiltersModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <string> // for std::string
#include <vector> // for std::vector

class vtkUnstructuredGrid;
namespace cgmesh
{
struct AdaptationOptions;
struct AdaptationSummary;
class ProcessGroup;
}

// A parameter's typed setter and getter, stored through Set/GetParameterValue.
#define cgmeshParameterMacro(name, type)                                                           \
  virtual void Set##name(type value)                                                               \
  {                                                                                                \
    this->SetParameterValue(#name, static_cast<double>(value));                                    \
  }                                                                                                \
  virtual type Get##name()                                                                         \
  {                                                                                                \
    return static_cast<type>(this->GetParameterValue(#name));                                      \
  }

#define cgmeshBooleanParameterMacro(name)                                                          \
  cgmeshParameterMacro(name, bool);                                                                \
  virtual void name##On()                                                                          \
  {                                                                                                \
    this->Set##name(true);                                                                         \
  }                                                                                                \
  virtual void name##Off()                                                                         \
  {                                                                                                \
    this->Set##name(false);                                                                        \
  }

#define cgmeshTextParameterMacro(name)                                                             \
  virtual void Set##name(const char* value)                                                        \
  {                                                                                                \
    this->SetParameterText(#name, value);                                                          \
  }                                                                                                \
  virtual const char* Get##name()                                                                  \
  {                                                                                                \
    return this->GetParameterText(#name);                                                          \
  }

class CGMESHFILTERS_EXPORT vtkCoarseGrainedMeshAdaptation : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkCoarseGrainedMeshAdaptation* New();
  vtkTypeMacro(vtkCoarseGrainedMeshAdaptation, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The parameters. Each one's range, default and meaning are in the parameter table
   * (Filters/Driver/AdaptationOptions.h), which also gives the command line's options and --help;
   * out-of-range values are clamped to the range.
   *
   * NumberOfPartitions (default 0, automatic): partitions, reduced with a warning for a smaller
   * mesh. Partitioner (AUTOMATIC_PARTITIONER): METIS on the dual graph or runs along a Hilbert
   * curve. RegionArrayName (default none): numeric cell array of material/region ids; unset, empty
   * or "None" (ParaView's "no array" entry) means no named array, unless the input has a cell
   * array called "None": then the input's integer cell arrays are kept together as material
   * labels (GetMaterialLabelArrays() says which). Any other name that is not a cell array of the
   * input is an error.
   * InterpolatedPointArrays (empty): integer point arrays to interpolate and round like fields;
   * every other integer point array is a labelling (node sets, contact flags): a new point takes
   * the value all its sources share, else 0. LabelPointArrays (empty): floating-point point
   * arrays to treat as such labels too (flags stored as floats); their values must be finite.
   * Either list naming an array the input does not have is an error.
   * PartitionByRegion (off) and PartitionsPerRegion (1): cut along the regions instead of METIS on
   * the whole mesh (needs RegionArrayName).
   * ColoringAlgorithm (GREEDY_LEAST_USED), Method (TEMPLATE), NumberOfIterations (1).
   * Template: MaximumEdgeLength (0: unused) or EdgeLengthFactor (0.5); or a size field:
   * SizeArrayName (a point or cell array of target edge lengths; none by default) and
   * SizeGradation (1.3) and Coarsen (on: edges shorter than h / sqrt(2) are collapsed at
   * vertices on no boundary or material interface), with the point array TargetEdgeLength (the
   * graded field), the cell array EdgeLengthRatio and the field data EdgesWithinSizeBounds and
   * EdgeSizeRatioHistogram in the output (Delaunay takes a size field too). RefinementRegions
   * ("2,5": region ids) and RefinementBox ("x0,y0,z0,x1,y1,z1"): refine only there (empty:
   * everywhere).
   * Delaunay: MaximumVolume (0: unused) or VolumeFactor (0.1), RadiusEdgeRatio (2, at least 1).
   * ImproveQuality (on), ImproveInput (on; Template: improve the input before refining it too)
   * and NumberOfImprovementPasses (2, in [0, 20]).
   * NumberOfThreads (0: all cores; the output does not depend on it).
   * MaximumNumberOfCells (100000000; 0: no limit): the size guard.
   * Diagnostics (off): also the text and possibly empty field data (names, fallback partitions).
   */
  cgmeshParameterMacro(NumberOfPartitions, int);
  cgmeshParameterMacro(Partitioner, int);
  cgmeshTextParameterMacro(RegionArrayName);
  cgmeshTextParameterMacro(InterpolatedPointArrays);
  cgmeshTextParameterMacro(LabelPointArrays);
  cgmeshBooleanParameterMacro(PartitionByRegion);
  cgmeshParameterMacro(PartitionsPerRegion, int);
  cgmeshParameterMacro(ColoringAlgorithm, int);
  cgmeshParameterMacro(Method, int);
  cgmeshParameterMacro(NumberOfIterations, int);
  cgmeshParameterMacro(MaximumEdgeLength, double);
  cgmeshParameterMacro(EdgeLengthFactor, double);
  cgmeshTextParameterMacro(SizeArrayName);
  cgmeshParameterMacro(SizeGradation, double);
  cgmeshBooleanParameterMacro(Coarsen);
  cgmeshTextParameterMacro(RefinementRegions);
  cgmeshTextParameterMacro(RefinementBox);
  cgmeshParameterMacro(MaximumVolume, double);
  cgmeshParameterMacro(VolumeFactor, double);
  cgmeshParameterMacro(RadiusEdgeRatio, double);
  cgmeshBooleanParameterMacro(ImproveQuality);
  cgmeshBooleanParameterMacro(ImproveInput);
  cgmeshParameterMacro(NumberOfImprovementPasses, int);
  cgmeshParameterMacro(NumberOfThreads, int);
  cgmeshParameterMacro(MaximumNumberOfCells, vtkIdType);
  cgmeshBooleanParameterMacro(Diagnostics);
  ///@}

  ///@{
  /**
   * The refinement box as ParaView's box widget gives it. With RefinementBoxEnabled (default off),
   * only tets whose bounding box meets [RefinementBoxOrigin, RefinementBoxOrigin +
   * RefinementBoxLength] are refined, exactly as RefinementBox "x0,y0,z0,x1,y1,z1" would refine
   * them (and so only with the Template method). The lengths must be finite and not negative.
   * The two ways are exclusive: a run with RefinementBoxEnabled and a RefinementBox text fails.
   * Not in the parameter table: the command line has --refine-box.
   */
  vtkSetMacro(RefinementBoxEnabled, bool);
  vtkGetMacro(RefinementBoxEnabled, bool);
  vtkBooleanMacro(RefinementBoxEnabled, bool);
  vtkSetVector3Macro(RefinementBoxOrigin, double);
  vtkGetVector3Macro(RefinementBoxOrigin, double);
  vtkSetVector3Macro(RefinementBoxLength, double);
  vtkGetVector3Macro(RefinementBoxLength, double);
  ///@}

  ///@{
  /**
   * Any parameter by its property name (as in the table). A numeric parameter is clamped to its
   * range; a Choice (Method, ColoringAlgorithm) is its index, a Boolean 0 or 1. Setting an unknown
   * name, or a number to RegionArrayName, is an error and changes nothing.
   */
  void SetParameterValue(const char* name, double value);
  double GetParameterValue(const char* name);
  void SetParameterText(const char* name, const char* value);
  const char* GetParameterText(const char* name);
  ///@}

  /**
   * The cell arrays the last run kept as material labels because RegionArrayName was None
   * (comma-separated; empty when a region array was named or the input has no integer cell
   * array). Cells whose values differ in any of them are treated as different materials:
   * improvement never crosses their interfaces and the Delaunay method keeps them.
   */
  const char* GetMaterialLabelArrays() const;

#if !defined(__VTK_WRAP__)
  ///@{
  /**
   * The last run's summary for C++ front ends: the resolved plan, counts, typed warnings and the
   * seconds per phase (AdaptationDriver.h), the seconds the input's conversion, the output grid
   * and the quality arrays took, and the whole run's. The summary is nullptr before a run and after
   * a run that stopped before refining.
   */
  const cgmesh::AdaptationSummary* GetLastSummary() const;
  double GetLastInputSeconds() const;
  double GetLastOutputSeconds() const;
  double GetLastQualitySeconds() const;
  double GetLastTotalSeconds() const;
  ///@}
#endif

  /**
   * How the mesh is cut into partitions (values of Partitioner).
   */
  enum Partitioners
  {
    AUTOMATIC_PARTITIONER = 0, // Hilbert for Template, METIS for Delaunay
    METIS = 1,                 // METIS k-way on the dual graph
    HILBERT = 2                // equal runs along a Hilbert curve through the tet centroids
  };
  void SetPartitionerToAutomatic()
  {
    this->SetPartitioner(AUTOMATIC_PARTITIONER);
  }
  void SetPartitionerToMetis()
  {
    this->SetPartitioner(METIS);
  }
  void SetPartitionerToHilbert()
  {
    this->SetPartitioner(HILBERT);
  }
  const char* GetPartitionerName()
  {
    return PartitionerToName(this->GetPartitioner());
  }
  ///@{
  /**
   * Conversion between Partitioners values and their names ("auto", "metis", "hilbert"); nullptr or
   * -1 for an unknown one.
   */
  static const char* PartitionerToName(int partitioner);
  static int PartitionerFromName(const char* name);
  ///@}

  /**
   * Serial refinement kernels run on the partitions (values of Method).
   */
  enum Methods
  {
    TEMPLATE = 0, // split long edges by conforming templates
    DELAUNAY = 1  // templates on interfaces, TetGen inside partitions
  };
  void SetMethodToTemplate()
  {
    this->SetMethod(TEMPLATE);
  }
  void SetMethodToDelaunay()
  {
    this->SetMethod(DELAUNAY);
  }

  /**
   * Name of the current method: "template" or "delaunay" (the names of the command line's --method
   * option).
   */
  const char* GetMethodName()
  {
    return MethodToName(this->GetMethod());
  }

  ///@{
  /**
   * Conversion between Methods values and their names; MethodToName returns nullptr for a value
   * out of range, MethodFromName returns -1 for an unknown name.
   */
  static const char* MethodToName(int method);
  static int MethodFromName(const char* name);
  ///@}

  /**
   * Colourings of the partition graph (values of ColoringAlgorithm). Greedy (first fit) is
   * unbalanced; Greedy-LU (least-used permissible colour) balances the colour sets; Iterative
   * (speculative parallel colouring with conflict rounds) and Recoloring (parallel rebalancing of
   * an initial colouring) use the threads. Every algorithm gives the same colours for any number
   * of threads.
   */
  enum ColoringAlgorithms
  {
    GREEDY = 0,
    GREEDY_LEAST_USED = 1,
    ITERATIVE = 2,
    RECOLORING = 3
  };
  void SetColoringAlgorithmToGreedy()
  {
    this->SetColoringAlgorithm(GREEDY);
  }
  void SetColoringAlgorithmToGreedyLeastUsed()
  {
    this->SetColoringAlgorithm(GREEDY_LEAST_USED);
  }
  void SetColoringAlgorithmToIterative()
  {
    this->SetColoringAlgorithm(ITERATIVE);
  }
  void SetColoringAlgorithmToRecoloring()
  {
    this->SetColoringAlgorithm(RECOLORING);
  }

  /**
   * Name of the current colouring: "greedy", "greedy-lu", "iterative" or "recoloring" (the names
   * of the command line's --coloring option).
   */
  const char* GetColoringAlgorithmName()
  {
    return ColoringAlgorithmToName(this->GetColoringAlgorithm());
  }

  ///@{
  /**
   * Conversion between ColoringAlgorithms values and their names; ColoringAlgorithmToName returns
   * nullptr for a value out of range, ColoringAlgorithmFromName returns -1 for an unknown name.
   */
  static const char* ColoringAlgorithmToName(int algorithm);
  static int ColoringAlgorithmFromName(const char* name);
  ///@}

protected:
  vtkCoarseGrainedMeshAdaptation();
  ~vtkCoarseGrainedMeshAdaptation() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // The region array name to use: empty when unset, empty or ParaView's "None" entry.
  std::string ResolveRegionArrayName(vtkUnstructuredGrid* input) const;
  // The size array's name, empty for none (or ParaView's "None" entry).
  std::string ResolveSizeArrayName(vtkUnstructuredGrid* input) const;
  // Reports an error and returns false unless every input cell is a linear tetrahedron or a
  // triangle, and PartitionByRegion has a region array to cut along.
  bool CheckInput(vtkUnstructuredGrid* input);

  // The stages of one run on this process's piece (the whole input in one process); each reports
  // its own error and returns false on failure.
  struct PieceRun;
  bool SeparateTriangles(PieceRun& run);
  bool ConvertPiece(
    PieceRun& run, const std::vector<std::string>& materialLabels, bool distributed);
  // Refines the piece into `output`. The output takes over the merged mesh's storage unless
  // `distributed` (the numbering across processes reads the mesh afterwards).
  bool AdaptPiece(PieceRun& run, const cgmesh::AdaptationOptions& options,
    vtkUnstructuredGrid* output, bool distributed);
  // Across processes: global point and cell ids, and ghost cells when the pipeline asks for them.
  void NumberAcrossProcesses(const cgmesh::ProcessGroup& group, const PieceRun& run,
    int ghostLevels, vtkUnstructuredGrid* output);

  // The parameters' values, kept as the driver's options.
  class vtkInternals;
  vtkInternals* Internals;

  bool RefinementBoxEnabled = false;
  double RefinementBoxOrigin[3] = { 0, 0, 0 };
  double RefinementBoxLength[3] = { 1, 1, 1 };

private:
  vtkCoarseGrainedMeshAdaptation(const vtkCoarseGrainedMeshAdaptation&) = delete;
  void operator=(const vtkCoarseGrainedMeshAdaptation&) = delete;
};

#endif
