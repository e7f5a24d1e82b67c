// Waiting on connections, not on the wall clock: a checker that starts a stream before every
// subscriber downstream is connected loses the first messages when the machine is busy (a
// registration with the master comes first, the TCP connection some time after it).
#pragma once

#include <gtest/gtest.h>
#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <xmlrpcpp/XmlRpc.h>

#include <cstdint>
#include <cstdio>

#include <string>

namespace imu_lab {
namespace connection_check {

// Whether the node `publisher` sends `topic` to the node `subscriber` (caller ids, e.g.
// "/calibration_corrector"), from the publisher's own bus information (XML-RPC getBusInfo): a
// message published from then on reaches the subscriber. (The subscriber's side of a connection
// exists a moment before the publisher's, so only the publisher's side says it is complete.)
inline bool sends(const std::string& publisher, const std::string& topic, const std::string& subscriber) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  request[1] = publisher;
  if (!ros::master::execute("lookupNode", request, response, payload, false)) return false;
  std::string host;
  std::uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port)) return false;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue arguments, result;
  arguments[0] = ros::this_node::getName();
  if (!client.execute("getBusInfo", arguments, result) || result.getType() != XmlRpc::XmlRpcValue::TypeArray ||
      result.size() < 3) {
    return false;
  }
  XmlRpc::XmlRpcValue connections = result[2];
  for (int i = 0; i < connections.size(); ++i) {
    XmlRpc::XmlRpcValue connection = connections[i];
    // [id, the subscriber's caller id, "o", transport, topic, ...]
    if (connection.size() >= 5 && static_cast<std::string>(connection[2]) == "o" &&
        static_cast<std::string>(connection[4]) == topic && static_cast<std::string>(connection[1]) == subscriber) {
      return true;
    }
  }
  return false;
}

// Polls until `ready` holds or timeout_s of wall time pass (a limit for a broken run, not a wait
// that a slow machine could outlast); returns whether it held. Does not spin the callbacks.
template <class Condition>
bool wait_until(const Condition& ready, double timeout_s) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
  while (ros::ok() && !ready()) {
    if (ros::WallTime::now() > deadline) return false;
    ros::WallDuration(0.05).sleep();
  }
  return ready();
}

// Plays `bag` into the graph (`rosbag play --clock --wait-for-subscribers`, then `play_arguments`;
// the bag comes first because --topics takes every argument after it) once `publisher` sends
// `topic` to this checker, so none of the node's output is lost, and spins the callbacks until
// `received_all` holds or timeout_s of wall time pass (a limit for a broken run). Waits for the
// player to end, then takes what is still queued. rosbag's output goes to `log_path`.
template <class Condition>
::testing::AssertionResult play_and_collect(const std::string& bag, const std::string& play_arguments,
                                            const std::string& log_path, const std::string& publisher,
                                            const std::string& topic, const Condition& received_all,
                                            double timeout_s) {
  if (!wait_until([&] { return sends(publisher, topic, ros::this_node::getName()); }, 60.0)) {
    return ::testing::AssertionFailure() << publisher << " never connected " << topic << " to this checker";
  }
  const std::string play = "rosbag play --clock --wait-for-subscribers --quiet --queue=100000 " + bag + " " +
                           play_arguments + " > " + log_path + " 2>&1";
  FILE* player = ::popen(play.c_str(), "r");
  if (player == nullptr) return ::testing::AssertionFailure() << "could not start: " << play;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
  while (ros::ok() && ros::WallTime::now() < deadline && !received_all()) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  const int status = ::pclose(player);
  ros::spinOnce();
  if (status != 0) return ::testing::AssertionFailure() << "rosbag play failed; see " << log_path;
  return ::testing::AssertionSuccess();
}

}  // namespace connection_check
}  // namespace imu_lab
