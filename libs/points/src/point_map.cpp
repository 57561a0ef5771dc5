#include "pmap/points/point_map.h"

#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>

namespace pmap::points {

std::size_t PointMap::addScan(const input::StructureScan& scan,
                              const mrpt::math::TPose3D& robot_pose) {
  const mrpt::poses::CPose3D robot(robot_pose);
  const Eigen::Matrix3d rot = robot.getRotationMatrix().asEigen();
  const Eigen::Vector3d trans(robot.x(), robot.y(), robot.z());

  ScanRecord record;
  record.index = scan.index;
  record.timestamp = scan.timestamp;
  record.label = scan.label;
  record.robot_pose = robot_pose;
  record.sensor_pose = (robot + mrpt::poses::CPose3D(scan.sensor_pose)).asTPose();
  record.first_point = xyz_.size();
  record.num_points = scan.points.size();
  record.rows = scan.rows;
  record.cols = scan.cols;
  record.organised = scan.organised;

  for (size_t i = 0; i < scan.points.size(); ++i) {
    xyz_.push_back(rot * scan.points[i] + trans);
    scan_.push_back(static_cast<std::int32_t>(scan.index));
    beam_.push_back(scan.beams[i]);
  }
  scans_.push_back(record);
  return scans_.size() - 1;
}

}  // namespace pmap::points
