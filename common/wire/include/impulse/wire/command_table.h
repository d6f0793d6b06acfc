#pragma once
/// The protocol's commands, one row per script word: the only list of them.
/// Adding a command is a message in proto/impulse.proto, a row here, and the
/// functions the row names (the server handler, the script parser, the
/// client builder); the server's dispatch and roles, the wire names, the
/// script grammar, impulse-cli --help and the grammar README.md and
/// docs/server.md must show (tests/net/command_table_test.cpp) all come
/// from the rows.
///
/// Each user expands the table with a macro taking the columns in order and
/// ignores the columns it cannot see (the server has no script parser, the
/// client no server handler):
///
///   Case     the ClientMessage oneof case without its `k` (kStep: Step)
///   field    the oneof field; also the command's wire name ("step")
///   role     Anyone; Owner for commands acting on the bodies or joints they
///            name (body_id, body_a, body_b, joint_id: a player must have
///            created them); Admin for commands that change everyone's world
///   handler  the server function applying it: server/src/command_handlers.cpp
///   word     the impulse-cli word
///   usage    its script grammar
///   help     one line for --help, README.md and docs/server.md
///   parser   the script words to the builder's arguments:
///            client/cli/command_parsers.cpp
///   builder  the client library's builder: impulse/client/commands.h
///
/// Two words may share a command (pause, resume): their rows name the same
/// case, field, role and handler.

// clang-format off
#define IMPULSE_COMMAND_TABLE(ROW)                                                        \
  ROW(LoadPreset, load_preset, Admin, loadPreset, "preset", "preset N [MATERIAL]",        \
      "load preset 0-21 (MATERIAL: the one preset 9 compares with SOLID)",                \
      parsePreset, client::loadPreset)                                                    \
  ROW(SetPaused, set_paused, Admin, setPaused, "pause", "pause",                          \
      "stop the tick clock", parsePause, client::setPaused)                               \
  ROW(SetPaused, set_paused, Admin, setPaused, "resume", "resume",                        \
      "restart the tick clock", parseResume, client::setPaused)                           \
  ROW(Step, step, Admin, step, "step", "step N (1 or more ticks)",                        \
      "while paused: advance exactly N ticks (reply has tick and state_hash)",            \
      parseStep, client::step)                                                            \
  ROW(SpawnCircle, spawn_circle, Anyone, spawnCircle, "circle",                           \
      "circle X Y R [MATERIAL] [static] [asleep] [nograv] [NAME=VALUE...]",             \
      "spawn a circle (NAME: density friction restitution damping angular-damping "       \
      "gravity-scale); reply has body_id",                                                \
      parseCircle, client::spawnCircle)                                                   \
  ROW(SpawnPolygon, spawn_polygon, Anyone, spawnPolygon, "polygon",                       \
      "polygon X1 Y1 X2 Y2 X3 Y3 ... [MATERIAL] [static] [asleep] [nograv] [NAME=VALUE...]",       \
      "spawn a convex polygon (world coordinates, either winding, 3-16 vertices)",        \
      parsePolygon, client::spawnPolygon)                                                 \
  ROW(SpawnCapsule, spawn_capsule, Anyone, spawnCapsule, "capsule",                       \
      "capsule X1 Y1 X2 Y2 R [MATERIAL] [static|kinematic] [asleep] [nograv] [NAME=VALUE...]",     \
      "spawn a capsule: the points within R of the segment X1 Y1 - X2 Y2",                \
      parseCapsule, client::spawnCapsule)                                                 \
  ROW(SpawnSegment, spawn_segment, Anyone, spawnSegment, "segment",                       \
      "segment X1 Y1 X2 Y2 [MATERIAL] [kinematic]",                                       \
      "spawn a static (or kinematic) segment: a wall or a piece of terrain",              \
      parseSegment, client::spawnSegment)                                                 \
  ROW(SpawnChain, spawn_chain, Anyone, spawnChain, "chain",                               \
      "chain X1 Y1 X2 Y2 X3 Y3 X4 Y4 ... [loop] [MATERIAL] [kinematic]",                  \
      "spawn terrain: one-sided segments through 4 or more points (loop: closed)",        \
      parseChain, client::spawnChain)                                                     \
  ROW(SpawnBody, spawn_body, Anyone, spawnBody, "body",                                   \
      "body X Y ANGLE PART... [MATERIAL] [static|kinematic] [asleep] [nograv] [NAME=VALUE...]",    \
      "spawn a compound body; PART: circle CX CY R | box CX CY HW HH | "                  \
      "capsule X1 Y1 X2 Y2 R (body-local)",                                               \
      parseBody, client::spawnBody)                                                       \
  ROW(SetTargetTransform, set_target_transform, Owner, setTargetTransform, "move-to",     \
      "move-to ID X Y [ANGLE]",                                                           \
      "move a body (a kinematic platform) to X Y, ANGLE over the next tick",              \
      parseTarget, client::setTargetTransform)                                            \
  ROW(SetTransform, set_transform, Owner, setTransform, "teleport",                       \
      "teleport ID X Y [ANGLE]",                                                          \
      "put a body's centre at X Y, turned to ANGLE (rad), at once; it keeps its velocity", \
      parseTarget, client::setTransform)                                                  \
  ROW(SetMaterial, set_material, Owner, setMaterial, "material", "material ID MATERIAL",   \
      "give every shape of a body the material; its mass follows",                        \
      parseBodyMaterial, client::setMaterial)                                             \
  ROW(SetBodyType, set_body_type, Owner, setBodyType, "body-type",                        \
      "body-type ID static|kinematic|dynamic",                                            \
      "change a body's type (dynamic needs a shape with area)",                           \
      parseBodyType, client::setBodyType)                                                 \
  ROW(SetGravity, set_gravity, Admin, setGravity, "gravity", "gravity GX GY",             \
      "set gravity", parsePoint, client::setGravity)                                      \
  ROW(NudgeGravity, nudge_gravity, Admin, nudgeGravity, "nudge", "nudge DX DY",           \
      "add to gravity", parsePoint, client::nudgeGravity)                                 \
  ROW(ResetGravity, reset_gravity, Admin, resetGravity, "reset-gravity", "reset-gravity", \
      "reset gravity to (0, -9.81)", parseNoArguments, client::resetGravity)              \
  ROW(Clear, clear, Admin, clear, "clear", "clear",                                       \
      "remove every body", parseNoArguments, client::clearWorld)                          \
  ROW(RemoveBody, remove_body, Owner,  removeBody, "remove", "remove ID",                 \
      "remove a body", parseBodyId, client::removeBody)                                   \
  ROW(ApplyImpulse, apply_impulse, Owner,  applyImpulse, "impulse",                       \
      "impulse ID JX JY [PX PY]", "apply an impulse (at a world point)",                  \
      parseImpulse, client::applyImpulse)                                                 \
  ROW(SetVelocity, set_velocity, Owner, setVelocity, "velocity", "velocity ID VX VY [W]",   \
      "set a body's velocity (m/s) and angular velocity W (rad/s, default 0)",            \
      parseVelocity, client::setVelocity)                                                 \
  ROW(SetShapeFlags, set_shape_flags, Owner, setShapeFlags, "flags",                       \
      "flags ID [sensor] [contact-events] [hit-events] [no-sensor-events] "               \
      "[category=N] [mask=N] [group=N]",                                                  \
      "set a body's shape flags: filter (N decimal or 0x hex), sensor, events",           \
      parseShapeFlags, client::setShapeFlags)                                             \
  ROW(SubscribeEvents, subscribe_events, Anyone, subscribeEvents, "events",               \
      "events on|off",                                                                    \
      "start or stop the stream of contact, hit and sensor events",                       \
      parseEvents, client::subscribeEvents)                                               \
  ROW(RayCast, ray_cast, Anyone, rayCast, "raycast",                                      \
      "raycast X Y DX DY [all] [category=N] [mask=N]",                                    \
      "the first shape (all: every one) the ray from X Y to X+DX Y+DY enters",            \
      parseRayCast, client::rayCast)                                                      \
  ROW(ShapeCast, shape_cast, Anyone, shapeCast, "shapecast",                              \
      "shapecast X Y ANGLE PART DX DY [category=N] [mask=N]",                             \
      "the first shape a PART (as in body) placed at X Y, ANGLE and moved by DX DY "      \
      "touches",                                                                          \
      parseShapeCast, client::shapeCast)                                                  \
  ROW(QueryAabb, query_aabb, Anyone, queryAabb, "overlap",                                \
      "overlap X1 Y1 X2 Y2 [category=N] [mask=N]",                                        \
      "the shapes whose bounding box overlaps the box X1 Y1 - X2 Y2",                     \
      parseOverlap, client::queryAabb)                                                    \
  ROW(QueryBody, query_body, Anyone, queryBody, "query", "query ID",                      \
      "description, state and mass properties of a body", parseBodyId, client::queryBody) \
  ROW(Ping, ping, Anyone, ping, "ping", "ping",                                           \
      "round trip and server statistics", parsePing, client::ping)                        \
  ROW(CreateJoint, create_joint, Owner,  createJoint, "distance",                         \
      "distance A B AX AY BX BY [LENGTH [K [DAMPING]]] [collide]",                        \
      "join A and B (B 0: the world) by a rod, or a spring of K N/m; reply has joint_id", \
      parseDistance, client::distanceJoint)                                               \
  ROW(CreateJoint, create_joint, Owner,  createJoint, "rope",                             \
      "rope A B AX AY BX BY [MAX_LENGTH] [collide]",                                      \
      "a rope: slack below MAX_LENGTH (default: the anchors' distance), never longer",    \
      parseRope, client::ropeJoint)                                                       \
  ROW(CreateJoint, create_joint, Owner,  createJoint, "revolute",                         \
      "revolute A B X Y [limit LO HI] [motor SPEED TORQUE] [spring K D] [collide]",       \
      "a pin at X Y (angles in rad, SPEED in rad/s)", parseRevolute,                      \
      client::revoluteJoint)                                                              \
  ROW(CreateJoint, create_joint, Owner,  createJoint, "prismatic",                        \
      "prismatic A B X Y DX DY [limit LO HI] [motor SPEED FORCE] [spring K D] [collide]", \
      "B slides along the axis DX DY through X Y, without turning", parsePrismatic,       \
      client::prismaticJoint)                                                             \
  ROW(CreateJoint, create_joint, Owner,  createJoint, "weld", "weld A B X Y [KL KA] [collide]", \
      "glue B to A at X Y (stiffness KL N/m, KA N*m/rad; 0 or none: rigid)", parseWeld,   \
      client::weldJoint)                                                                  \
  ROW(CreateJoint, create_joint, Owner,  createJoint, "wheel",                            \
      "wheel A B X Y DX DY [spring K D] [motor SPEED TORQUE] [collide]",                  \
      "wheel B at X Y on a suspension along DX DY of car body A", parseWheel,             \
      client::wheelJoint)                                                                 \
  ROW(CreateJoint, create_joint, Owner,  createJoint, "mouse",                            \
      "mouse A X Y MAX_FORCE [K D]",                                                      \
      "pull A's point X Y towards a target (first X Y; move it with target)",            \
      parseMouse, client::mouseJoint)                                                     \
  ROW(UpdateJoint, update_joint, Owner,  updateJoint, "target", "target J X Y",           \
      "move mouse joint J's target", parseJointTarget, client::setJointTarget)            \
  ROW(UpdateJoint, update_joint, Owner,  updateJoint, "motor", "motor J SPEED [MAX]",     \
      "set joint J's motor speed (and max torque or force)", parseJointMotor,             \
      client::setJointMotor)                                                              \
  ROW(RemoveJoint, remove_joint, Owner,  removeJoint, "remove-joint", "remove-joint J",   \
      "remove a joint", parseBodyId, client::removeJoint)                                \
  ROW(QueryJoint, query_joint, Anyone, queryJoint, "query-joint", "query-joint J",        \
      "a joint's description, reaction force and torque, length, angle", parseBodyId,   \
      client::queryJoint)                                                                 \
  ROW(SetTimeScale, set_time_scale, Admin, setTimeScale, "time-scale", "time-scale S",    \
      "simulated time runs S times wall time (0.01-16), same step size",                  \
      parseTimeScale, client::setTimeScale)                                             \
  ROW(ListRooms, list_rooms, Anyone, listRooms, "rooms", "rooms",                         \
      "the server's rooms: name, clients, bodies, tick (reply is a RoomList)",            \
      parseNoArguments, client::listRooms)                                                \
  ROW(SaveScene, save_scene, Anyone, saveScene, "save", "save FILE",                      \
      "write the whole world, bit-exact, to FILE (a Scene message, docs/scenes.md)",      \
      parseSceneFileName, client::saveScene)                                              \
  ROW(LoadScene, load_scene, Admin, loadScene, "load", "load FILE",                       \
      "replace the world with the scene in FILE; it steps on as the saved one did",       \
      parseSceneFile, client::loadScene)                                                  \
  ROW(AddField, add_field, Admin, addField, "gravitation", "gravitation G",               \
      "Newton's gravitation between all bodies, constant G; reply has field_id",          \
      parseGravitation, client::gravitationField)                                         \
  ROW(AddField, add_field, Admin, addField, "fluid",                                      \
      "fluid DENSITY DRAG ANGULAR_DRAG CX CY X1 Y1 X2 Y2 X3 Y3 ...",                      \
      "a liquid in a convex polygon, drag rates 1/s, current (CX, CY) m/s",               \
      parseFluid, client::fluidField)                                                     \
  ROW(AddField, add_field, Admin, addField, "fan", "fan X Y DX DY SPEED RANGE SPREAD",    \
      "air blowing from (X, Y) along (DX, DY) at SPEED m/s, to RANGE m, half-angle SPREAD", \
      parseFan, client::fanField)                                                         \
  ROW(RemoveField, remove_field, Admin, removeField, "remove-field", "remove-field F",     \
      "remove a field", parseBodyId, client::removeField)                                 \
  ROW(SetInterestArea, set_interest_area, Anyone, setInterestArea, "area",                \
      "area X1 Y1 X2 Y2 | area all",                                                      \
      "receive only the bodies inside the box X1 Y1 - X2 Y2 (all: the whole room)",       \
      parseInterestArea, client::setInterestArea)                                         \
  ROW(SetBandwidthBudget, set_bandwidth_budget, Anyone, setBandwidthBudget, "budget",     \
      "budget BYTES_PER_SECOND | budget off",                                             \
      "send this client at most so many snapshot bytes a second, most important first",   \
      parseBandwidthBudget, client::setBandwidthBudget)
// clang-format on
