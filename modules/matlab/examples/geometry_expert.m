function expert = geometry_expert()
%GEOMETRY_EXPERT  The low-level geometry expert in MATLAB/Octave.
%   A faithful port of the C++ one (modules/experts/geometry, reference
%   points of lib/scene/object_geometry) and of its Python port
%   (modules/python/examples/geometry_expert.py), with the same parameter
%   and, fed the same inputs, the same GEOMETRY messages bit for bit.
%
%   Octave, from the repository's root (modules/matlab/README.md):
%     octave-cli --quiet --no-history modules/matlab/run_expert.m \
%       modules/matlab/examples/geometry_expert.m --interface
%     ./beft run scenarios/yard.xml --external geometry="octave-cli --quiet --no-history \
%       modules/matlab/run_expert.m modules/matlab/examples/geometry_expert.m"
%   MATLAB: status = beft_run_expert(geometry_expert(), '--url', 'ws://127.0.0.1:8765')
  expert = beft_expert('geometry', description());
  expert = beft_scene_input(expert);
  expert = beft_tick_input(expert, 'ROBOT_STATE', 'beft.robot_state_t');
  expert = beft_output(expert, 'GEOMETRY', 'beft.geometry_percepts_t');
  expert = beft_parameter(expert, 'flag', 'every_object', false, ...
                          ['a percept for every scene object, also the silent ones behind the camera, which no ' ...
                           'expert reads (off: only those that sound now or may be in front of the camera)']);
  expert.fire = @fire;
end

function text = description()
  text = ['Low-level geometry expert, in MATLAB/Octave: for every scene object that sounds now or may be in ' ...
          'front of the camera (every_object: all of them), the 3-D distance d_i from the platform centre (on ' ...
          'the ground) to the object centre (half its height), the azimuth alpha_i relative to the nose ' ...
          '(platform yaw + head yaw; (-180, 180] deg, positive to the left) and the elevation relative to the ' ...
          'head pitch; flags objects that sound now. Reads GT_OBJECTS and ROBOT_STATE of the fired tick, ' ...
          'writes GEOMETRY.'];
end

function [outputs, failure, state] = fire(firing, inputs, parameters, state)
  outputs = struct();
  failure = '';
  if isempty(inputs.GT_OBJECTS)
    failure = sprintf('no GT_OBJECTS for tick %d', firing.tick);
  elseif isempty(inputs.ROBOT_STATE)
    failure = sprintf('no ROBOT_STATE for tick %d', firing.tick);
  else
    outputs.GEOMETRY = estimate_geometry(inputs.GT_OBJECTS, inputs.ROBOT_STATE, parameters.every_object);
  end
end

function geometry = estimate_geometry(scene, robot, every_object)
  percepts = struct('object_id', {}, 'distance', {}, 'azimuth', {}, 'elevation', {}, 'acoustic', {});
  for k = 1:numel(scene.objects)
    o = scene.objects(k);
    if every_object || perceivable(robot, o)
      percepts(end + 1) = percept_of(robot, o); %#ok<AGROW>
    end
  end
  geometry = struct('utime', scene.utime, 'tick', scene.tick, 'num_percepts', numel(percepts), ...
                    'percepts', percepts);
end

% Sounds now, or some part of it may be in front of the camera.
function yes = perceivable(robot, o)
  if is_sounding(o)
    yes = true;
  elseif ~has_visual(o)
    yes = false;
  else
    heading = nose_heading_deg(robot) * deg_to_rad();
    ahead = (o.x - robot.x) * cos(heading) + (o.y - robot.y) * sin(heading);
    extent = 0.5 * hypot(o.size_x, o.size_y);
    tilt = std_min(abs(robot.head_pitch), 80.0) * deg_to_rad();
    seen_behind = std_max(robot.camera_height, o.z + o.size_z) * tan(tilt);
    yes = ahead > -(extent + seen_behind + 0.5);
  end
end

function percept = percept_of(robot, o)
  oz = object_centre_z(o);
  dx = o.x - robot.x;
  dy = o.y - robot.y;
  dz = oz - robot.camera_height;
  elevation = atan2(dz, hypot(dx, dy)) / deg_to_rad() - robot.head_pitch;
  percept = struct('object_id', o.id, ...
                   'distance', beft_distance(robot.x, robot.y, 0.0, o.x, o.y, oz), ...
                   'azimuth', beft_azimuth(robot.x, robot.y, nose_heading_deg(robot), o.x, o.y), ...
                   'elevation', elevation, 'acoustic', is_sounding(o));
end

function yes = has_visual(o)
  yes = o.shape == 1 || o.shape == 2;  % SHAPE_BOX, SHAPE_CYLINDER
end

function yes = is_sounding(o)
  yes = o.has_acoustic && o.sound_active;
end

function heading = nose_heading_deg(robot)
  heading = robot.yaw + robot.head_yaw;
end

function z = object_centre_z(o)
  half_height = 0.0;
  if has_visual(o)
    half_height = 0.5 * o.size_z;
  end
  z = o.z + half_height;  % + 0.0 too: -0 becomes 0, as in C++
end

function factor = deg_to_rad()
  factor = pi / 180.0;
end

% std::min and std::max: the second only when strictly smaller (larger).
function m = std_min(a, b)
  m = a;
  if b < a
    m = b;
  end
end

function m = std_max(a, b)
  m = a;
  if a < b
    m = b;
  end
end
