// haros_arch stand-in: ROS 1 sound_play's C++ client (declarations only), for a workspace
// that has sound_play (audio_common) installed, not as sources. A SoundClient advertises
// sound_play/SoundRequest on the topic given, relative to the handle given, or on
// ``robotsound`` of a ``ros::NodeHandle()`` (the node's namespace) when built with no
// argument (sound_play.h's init: ``nh.advertise<sound_play::SoundRequest>(topic, 5)``);
// that advertisement is the API row (extract/cpp/api.py, SOUND_PLAY). Saying, playing and
// stopping publish on it and make no other ROS call.
#ifndef HAROS_STANDIN_SOUND_PLAY_SOUND_PLAY_H
#define HAROS_STANDIN_SOUND_PLAY_SOUND_PLAY_H
#include <string>
#include <ros/ros.h>

namespace sound_play {

// the deprecated name, as sound_play had it before its class of that name
#define SoundHandle SoundClient

class SoundClient {
 public:
  class Sound {
   public:
    void play();
    void repeat();
    void stop();
  };

  SoundClient(ros::NodeHandle& nh, const std::string& topic);
  SoundClient();
  virtual ~SoundClient();

  Sound voiceSound(const std::string& s);
  Sound voiceSound(const std::string& s, float volume);
  Sound waveSound(const std::string& s);
  Sound waveSound(const std::string& s, float volume);
  Sound waveSoundFromPkg(const std::string& p, const std::string& s);
  Sound waveSoundFromPkg(const std::string& p, const std::string& s, float volume);
  Sound builtinSound(int id);
  Sound builtinSound(int id, float volume);

  void say(const std::string& s);
  void say(const std::string& s, const std::string& voice);
  void say(const std::string& s, const std::string& voice, float volume);
  void repeat(const std::string& s);
  void repeat(const std::string& s, const std::string& voice);
  void repeat(const std::string& s, const std::string& voice, float volume);
  void stopSaying(const std::string& s);
  void stopsaying(const std::string& s);
  void playWave(const std::string& s);
  void playWave(const std::string& s, float volume);
  void playwave(const std::string& s);
  void startWave(const std::string& s);
  void startWave(const std::string& s, float volume);
  void startwave(const std::string& s);
  void stopWave(const std::string& s);
  void stopwave(const std::string& s);
  void playWaveFromPkg(const std::string& p, const std::string& s);
  void playWaveFromPkg(const std::string& p, const std::string& s, float volume);
  void startWaveFromPkg(const std::string& p, const std::string& s);
  void startWaveFromPkg(const std::string& p, const std::string& s, float volume);
  void stopWaveFromPkg(const std::string& p, const std::string& s);
  void play(int sound);
  void play(int sound, float volume);
  void start(int sound);
  void start(int sound, float volume);
  void stop(int sound);
  void stopAll();
  void stopall();
  void setQuiet(bool state);
};

typedef SoundClient::Sound Sound;

}  // namespace sound_play
#endif
