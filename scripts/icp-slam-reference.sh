#!/usr/bin/env bash
# Regenerates the reference of tests/mapper/sena_icp_test.cpp: runs MRPT's own
# icp-slam (Debian package mrpt-apps) on MRPT's SENA log with the [ICP] and
# [MappingApplication*] sections of config/mrpt-sena.ini, and prints the final
# pose of its log_estimated_path.txt (step x y yaw).
set -euo pipefail
cd "$(dirname "$0")/.."
rawlog="/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# icp-slam also needs its own application keys, read from [MappingApplication].
sed -n '/^\[ICP\]/,$p' config/mrpt-sena.ini | sed "s#^\[MappingApplication\]\$#[MappingApplication]\n\
rawlog_offset = 0\nlogOutput_dir = $work/out\nLOG_FREQUENCY = 0\nSAVE_3D_SCENE = 0\nSAVE_POSE_LOG = 0\n\
CAMERA_3DSCENE_FOLLOWS_ROBOT = 0\nSHOW_PROGRESS_3D_REAL_TIME = 0\nSHOW_PROGRESS_3D_REAL_TIME_DELAY_MS = 0\n\
SHOW_LASER_SCANS_3D = 0#" > "$work/icp-slam.ini"
icp-slam "$work/icp-slam.ini" "$rawlog" < /dev/null > "$work/icp-slam.log" 2>&1
echo "icp-slam $(dpkg-query -W -f='${Version}' mrpt-apps 2>/dev/null || echo '?'): final pose (step x y yaw):"
tail -n 1 "$work/out/log_estimated_path.txt"
