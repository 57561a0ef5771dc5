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

void PointMap::moveScan(std::size_t record, const mrpt::math::TPose3D& robot_pose) {
  ScanRecord& s = scans_.at(record);
  const mrpt::poses::CPose3D old_robot(s.robot_pose);
  const mrpt::poses::CPose3D new_robot(robot_pose);
  const Eigen::Matrix3d r_old = old_robot.getRotationMatrix().asEigen();
  const Eigen::Matrix3d r_new = new_robot.getRotationMatrix().asEigen();
  const Eigen::Vector3d t_old(old_robot.x(), old_robot.y(), old_robot.z());
  const Eigen::Vector3d t_new(new_robot.x(), new_robot.y(), new_robot.z());
  const Eigen::Matrix3d rot = r_new * r_old.transpose();
  for (std::size_t i = s.first_point; i < s.first_point + s.num_points; ++i) {
    xyz_[i] = rot * (xyz_[i] - t_old) + t_new;
  }
  const mrpt::poses::CPose3D sensor_on_robot = mrpt::poses::CPose3D(s.sensor_pose) - old_robot;
  s.sensor_pose = (new_robot + sensor_on_robot).asTPose();
  s.robot_pose = robot_pose;
}

}  // namespace pmap::points
