/**
 * @class   vtkCoarseGrainedMeshAdaptation
 * @brief   refine a tetrahedral mesh in parallel by running a serial kernel on coloured partitions
 *
 * The input (linear tetrahedra only) is partitioned with METIS into NumberOfPartitions parts, or,
 * with PartitionByRegion, along the regions of RegionArrayName into PartitionsPerRegion parts
 * each. The partition graph (partitions sharing a vertex) is coloured with ColoringAlgorithm, and
 * for each of NumberOfIterations passes the partitions of one colour are refined concurrently:
 * edges longer than the threshold are split by conforming templates, and interface splits are
 * handed to the neighbours that follow.
 * The threshold is MaximumEdgeLength when positive, else EdgeLengthFactor times the input's mean
 * edge length.
 *
 * The output is one conforming tetrahedral grid. Input cell data is copied to every child cell and
 * input point data is interpolated linearly onto new points. The output also holds the cell arrays
 * PartitionId, ColorId, EdgeRatio and MinDihedralAngle (vtkMeshQuality, degrees) and field data
 * with the colour, partition and thread counts, the threshold, the colouring (ColoringAlgorithm,
 * by name), the colour populations (PartitionsPerColor and CellsPerColor, one tuple per colour),
 * ColorBalance (largest colour over the mean, in partitions) and the seconds spent per phase
 * (PartitionSeconds, GraphSeconds, ColorSeconds, HealSeconds, AdaptSeconds, PostSeconds,
 * MergeSeconds, QualitySeconds, TotalSeconds).
 * The output does not depend on NumberOfThreads.
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

  ///@{
  /**
   * Edges longer than this absolute length are split. Not used when not positive (default 0).
   */
  vtkSetMacro(MaximumEdgeLength, double);
  vtkGetMacro(MaximumEdgeLength, double);
  ///@}

  ///@{
  /**
   * Split threshold as a fraction of the input's mean edge length, used when MaximumEdgeLength is
   * not positive. Default 0.5.
   */
  vtkSetClampMacro(EdgeLengthFactor, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(EdgeLengthFactor, double);
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
  double MaximumEdgeLength;
  double EdgeLengthFactor;
  int NumberOfThreads;
  char* RegionArrayName;
  int ColoringAlgorithm;
  bool PartitionByRegion;
  int PartitionsPerRegion;

private:
  vtkCoarseGrainedMeshAdaptation(const vtkCoarseGrainedMeshAdaptation&) = delete;
  void operator=(const vtkCoarseGrainedMeshAdaptation&) = delete;
};

#endif
