function firing = firing_of(fire)
% One FIRE token as fire gets it.
  firing = struct('expert', fire.expert, 'transition', fire.transition, 'tick', fire.tick, ...
                  'utime', fire.utime, 'firing_id', fire.firing_id);
end
